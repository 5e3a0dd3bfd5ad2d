//! Validation of a parsed scenario and its conversion into a [`hawser::Model`].
//! Every problem is collected (not just the first) with its file position.

use super::diagnostics::{Diagnostic, ScenarioError, closest, line_number};
use super::schema::*;
use crate::results::OutputChannel;
use hawser::analysis::{Channel, Object};
use hawser::math::{Quat, Vec3};
use hawser::model::*;
use hawser::physics::environment::{Current, Environment};
use hawser::physics::hydrodynamics::{DragModel, LoadingFunction};
use hawser::physics::material::{AxialDamping, AxialStiffness};
use hawser::physics::obstacles::{Obstacle, ObstacleDamping, ObstacleShape};
use hawser::physics::seabed::{ContactDamping, FrictionLaw, Seabed};
use hawser::physics::waves::{
    IrregularSea, MAX_SPREADING, RegularWave, SeaState, Spectrum, Stretching, WaveSpec, Waves,
    wavenumber,
};
use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

mod bodies;
mod sea;
mod winch;
pub use bodies::orientation_from_degrees;
pub use sea::{read_elevation_file, record_components};

/// A scenario read from a file: the model, its output channels and where things are.
#[derive(Clone, Debug)]
pub struct LoadedScenario {
    /// The model.
    pub model: Model,
    /// Time-series channels (defaults plus `simulation.channels`).
    pub channels: Vec<OutputChannel>,
    /// Whether `[simulation]` was given.
    pub has_simulation: bool,
    /// Span of `simulation.time_step`, for step errors.
    pub time_step_span: Option<Range<usize>>,
    /// What the file was.
    pub format: InputFormat,
}

/// The format of an input file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputFormat {
    /// A hawser scenario (TOML).
    Toml,
    /// A MoorDyn v2 input deck. Its `dtM` was chosen for MoorDyn's integrator: where it is
    /// above hawser's stability limit, hawser takes the limit instead of refusing the step.
    MoorDyn,
}

struct Builder<'a> {
    file: &'a Path,
    source: &'a str,
    errors: Vec<Diagnostic>,
}

/// A range check on a number: predicate and its description with unit.
struct Check {
    ok: fn(f64) -> bool,
    expected: &'static str,
}

const POSITIVE: fn(f64) -> bool = |x| x > 0.0;
const NON_NEGATIVE: fn(f64) -> bool = |x| x >= 0.0;
/// Polynomial order of `dg` sections when the file gives none (the DG paper's choice, N = 20, P = 4).
const DEFAULT_DG_ORDER: usize = 4;

impl<'a> Builder<'a> {
    fn diag(
        &self,
        span: Option<Range<usize>>,
        key: &str,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::new(self.file, self.source, span, key, message)
    }

    /// Refuses an object name that cannot be a channel prefix (empty, or with `.`, `,` or a
    /// quote); `kind` is "point", "line", …, `example` a channel it would name.
    fn check_channel_name(&mut self, name: &Spanned<String>, key: &str, kind: &str, example: &str) {
        let n = name.get_ref();
        if n.contains(['.', ',', '"']) || n.is_empty() {
            let d = self
                .diag(
                    Some(name.span()),
                    key,
                    format!("{kind} names must be non-empty without `.`, `,` or quotes"),
                )
                .hint(format!("they become channel names such as `{example}`"));
            self.push(d);
        }
    }

    fn push(&mut self, d: Diagnostic) {
        self.errors.push(d);
    }

    /// 1-based line of a byte offset, for "first defined on line N" hints.
    fn line_of(&self, span: Range<usize>) -> usize {
        line_number(self.source, span.start)
    }

    /// Checks a number is finite and in range; returns it (or a harmless default on error).
    fn num(&mut self, v: &Spanned<f64>, key: &str, check: Check, hint: &str) -> f64 {
        let x = *v.get_ref();
        if !x.is_finite() || !(check.ok)(x) {
            let d = self
                .diag(Some(v.span()), key, format!("`{key}` is out of range"))
                .expected(check.expected)
                .hint(hint);
            self.push(d);
            return 1.0;
        }
        x
    }

    fn opt(
        &mut self,
        v: &Option<Spanned<f64>>,
        key: &str,
        default: f64,
        check: Check,
        hint: &str,
    ) -> f64 {
        match v {
            Some(v) => self.num(v, key, check, hint),
            None => default,
        }
    }

    fn vec3(&mut self, v: &Spanned<[f64; 3]>, key: &str) -> Vec3 {
        let a = v.get_ref();
        if a.iter().any(|x| !x.is_finite()) {
            let d = self
                .diag(
                    Some(v.span()),
                    key,
                    format!("`{key}` has a non-finite component"),
                )
                .expected("three finite numbers [m]");
            self.push(d);
        }
        Vec3::new(a[0], a[1], a[2])
    }

    fn not_for(
        &mut self,
        present: bool,
        span: Option<Range<usize>>,
        key: &str,
        kind: &str,
        applies: &str,
    ) {
        if present {
            let d = self
                .diag(span, key, format!("`{key}` does not apply to {kind}"))
                .hint(format!("remove it; it applies to {applies}"));
            self.push(d);
        }
    }
}

fn span_of<T>(v: &Option<Spanned<T>>) -> Option<Range<usize>> {
    v.as_ref().map(|s| s.span())
}

/// Reads and validates scenario `source` (the text of `file`).
pub fn build(file: &Path, source: &str) -> Result<LoadedScenario, ScenarioError> {
    let scenario: Scenario = toml::from_str(source).map_err(|e| schema_errors(file, source, &e))?;
    build_scenario(file, source, &scenario)
}

/// Validates a scenario whose values carry spans into `source` (the text of `file`: the TOML
/// file itself, or a MoorDyn deck the scenario was converted from).
pub fn build_scenario(
    file: &Path,
    source: &str,
    scenario: &Scenario,
) -> Result<LoadedScenario, ScenarioError> {
    let mut b = Builder {
        file,
        source,
        errors: Vec::new(),
    };
    let environment = build_environment(&mut b, scenario.environment.as_ref());
    let (line_types, type_index) = build_line_types(&mut b, &scenario.line_types);
    let body_names: Vec<String> = scenario
        .bodies
        .iter()
        .map(|s| s.name.get_ref().clone())
        .collect();
    let (points, point_index) = build_points(&mut b, &scenario.points, &environment, &body_names);
    let lines = build_lines(&mut b, &scenario.lines, &type_index, &point_index);
    check_free_points_held(&mut b, &scenario.points, &lines, &points);
    if scenario.lines.is_empty() {
        let d = b
            .diag(Some(0..0), "lines", "the scenario defines no lines")
            .expected("at least one [[lines]] table")
            .hint("add a line between two points; docs/scenario.md has a complete minimal example");
        b.push(d);
    }
    for (i, p) in scenario.points.iter().enumerate() {
        if let Some(li) = scenario
            .lines
            .iter()
            .position(|l| l.name.get_ref() == p.name.get_ref())
        {
            let d = b
                .diag(
                    Some(p.name.span()),
                    &format!("points[{i}].name"),
                    format!("point `{}` has the name of line {}", p.name.get_ref(), li),
                )
                .hint("points and lines share the channel namespace: give them different names");
            b.push(d);
        }
    }
    let taken: HashMap<String, &str> = scenario
        .points
        .iter()
        .map(|p| (p.name.get_ref().clone(), "point"))
        .chain(
            scenario
                .lines
                .iter()
                .map(|l| (l.name.get_ref().clone(), "line")),
        )
        .collect();
    let bodies = bodies::build_bodies(&mut b, &scenario.bodies, &taken, &environment);
    let mut environment = environment;
    environment.obstacles = build_obstacles(&mut b, scenario, &environment);
    let (settings, time_step_span) = build_settings(&mut b, scenario.simulation.as_ref());
    let mut model = Model {
        environment,
        line_types,
        lines,
        points,
        bodies,
        settings,
    };
    model.settings.release = build_release(&mut b, scenario.simulation.as_ref(), &model);
    let channels = build_channels(&mut b, scenario.simulation.as_ref(), &model);
    check_steady_tow(&mut b, scenario.simulation.as_ref(), &model);
    if b.errors.is_empty()
        && let Err(e) = model.validate()
    {
        let d = b.diag(None, "", e.to_string());
        b.push(d);
    }
    if !b.errors.is_empty() {
        b.errors.sort_by_key(|d| (d.line, d.column));
        return Err(ScenarioError {
            diagnostics: b.errors,
        });
    }
    if model.environment.depth.is_infinite() {
        model.environment.seabed.stiffness = 0.0;
    }
    Ok(LoadedScenario {
        model,
        channels,
        has_simulation: scenario.simulation.is_some(),
        time_step_span,
        format: InputFormat::Toml,
    })
}

/// The first error of the file and, if the TOML itself is valid, the first error of every
/// other table: each section and each `[[...]]` element is checked on its own.
fn schema_errors(file: &Path, source: &str, first: &toml::de::Error) -> ScenarioError {
    use serde::Deserialize;
    use toml::de::{DeValue, ValueDeserializer};
    let mut errors = vec![toml_error(file, source, first)];
    if let Ok(doc) = toml::de::DeTable::parse(source) {
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
                let d = toml_error(file, source, &e);
                if !errors
                    .iter()
                    .any(|x| (x.line, x.column) == (d.line, d.column))
                {
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
fn toml_error(file: &Path, source: &str, e: &toml::de::Error) -> Diagnostic {
    let message = e.message().trim().to_string();
    let quoted: Vec<&str> = message.split('`').skip(1).step_by(2).collect();
    let first = quoted.first().copied().unwrap_or("");
    let span = e.span();
    let mut at = span
        .as_ref()
        .map(|s| key_at(source, s.start))
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
    let line_of = |offset: usize| line_number(source, offset);
    let one_of = |known: &[&str]| {
        let list: Vec<String> = known.iter().map(|q| format!("`{q}`")).collect();
        format!("one of {}", list.join(", "))
    };
    let mut d = Diagnostic::new(file, source, span.clone(), path.clone(), message.clone());
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

/// Finds the innermost key or value at `offset` in a best-effort parse of `source`.
fn key_at(source: &str, offset: usize) -> KeyAt {
    let (doc, _) = toml::de::DeTable::parse_recoverable(source);
    let mut at = KeyAt::default();
    if find_in_table(doc.get_ref(), offset, &mut at) {
        return at;
    }
    // Not inside a parsed key or value (e.g. a duplicate key, which the parser drops): take
    // the table whose header is the last before `offset`, and the key written at `offset`.
    let mut best = (0, Vec::new(), doc.get_ref());
    last_header(source, doc.get_ref(), offset, &mut Vec::new(), &mut best);
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
    let inner = match v.get_ref() {
        toml::de::DeValue::Table(t) => find_in_table(t, offset, at),
        toml::de::DeValue::Array(a) => a.iter().enumerate().any(|(i, item)| {
            at.path.push(Step::Index(i));
            let found = find_in_value(item, offset, at);
            if !found {
                at.path.pop();
            }
            found
        }),
        _ => false,
    };
    inner || v.span().contains(&offset)
}

/// The span of the key at `path` (e.g. `["environment", "seabed"]`), if written.
fn key_span(source: &str, path: &[&str]) -> Option<Range<usize>> {
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
    let schema = serde_json::to_value(schemars::schema_for!(Scenario)).ok()?;
    let defs = &schema["$defs"];
    let mut node = &schema;
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

fn build_environment(b: &mut Builder, spec: Option<&EnvironmentSpec>) -> Environment {
    let default = EnvironmentSpec::default();
    let e = spec.unwrap_or(&default);
    let mut env = Environment {
        gravity: b.opt(
            &e.gravity,
            "environment.gravity",
            9.80665,
            Check {
                ok: NON_NEGATIVE,
                expected: "m/s², ≥ 0",
            },
            "9.80665 on Earth",
        ),
        water_density: b.opt(
            &e.water_density,
            "environment.water_density",
            1025.0,
            Check {
                ok: POSITIVE,
                expected: "kg/m³, > 0",
            },
            "sea water is about 1025 kg/m³",
        ),
        air_density: b.opt(
            &e.air_density,
            "environment.air_density",
            1.225,
            Check {
                ok: NON_NEGATIVE,
                expected: "kg/m³, ≥ 0",
            },
            "air is about 1.225 kg/m³",
        ),
        depth: f64::INFINITY,
        seabed: Seabed::default(),
        current: Current::None,
        waves: Waves::None,
        wave_kinematics: Default::default(),
        obstacles: Vec::new(),
    };
    if let Some(d) = &e.depth {
        let errors = b.errors.len();
        env.depth = b.num(
            d,
            "environment.depth",
            Check {
                ok: POSITIVE,
                expected: "m, > 0 (the seabed is at z = −depth)",
            },
            "depth is positive; the seabed lies at z = −depth",
        );
        if b.errors.len() > errors {
            env.depth = f64::INFINITY;
        }
    }
    if let Some(s) = &e.seabed {
        let d = Seabed::default();
        env.seabed = Seabed {
            stiffness: b.opt(
                &s.stiffness,
                "environment.seabed.stiffness",
                d.stiffness,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "Pa/m, ≥ 0",
                },
                "3e6 Pa/m is a firm bed",
            ),
            damping: match (&s.damping_ratio, &s.damping) {
                (Some(_), Some(c)) => {
                    let d = b
                        .diag(
                            Some(c.span()),
                            "environment.seabed.damping",
                            "give either `damping_ratio` or `damping`, not both",
                        )
                        .hint("`damping_ratio` scales with each cable's mass; `damping` is per contact area");
                    b.push(d);
                    ContactDamping::Ratio(1.0)
                }
                (_, Some(c)) => ContactDamping::PerArea(b.num(
                    c,
                    "environment.seabed.damping",
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "Pa·s/m, ≥ 0",
                    },
                    "MoorDyn's cBot, e.g. 3e5 Pa·s/m",
                )),
                (ratio, None) => ContactDamping::Ratio(b.opt(
                    ratio,
                    "environment.seabed.damping_ratio",
                    1.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0 (1 = critical)",
                    },
                    "use 1 for critical damping",
                )),
            },
            friction_coefficient: b.opt(
                &s.friction_coefficient,
                "environment.seabed.friction_coefficient",
                d.friction_coefficient,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0",
                },
                "typical values are 0.2–1.0",
            ),
            friction_velocity: b.opt(
                &s.friction_velocity,
                "environment.seabed.friction_velocity",
                d.friction_velocity,
                Check {
                    ok: POSITIVE,
                    expected: "m/s, > 0",
                },
                "a small speed such as 0.01 m/s",
            ),
            friction_law: match &s.friction_damping {
                Some(c) => FrictionLaw::Viscous {
                    damping: b.num(
                        c,
                        "environment.seabed.friction_damping",
                        Check {
                            ok: POSITIVE,
                            expected: "N·s/m per node, > 0",
                        },
                        "MoorDyn's default FricDamp is 200 N·s/m",
                    ),
                    static_scale: b.opt(
                        &s.static_friction_scale,
                        "environment.seabed.static_friction_scale",
                        1.0,
                        Check {
                            ok: POSITIVE,
                            expected: "-, > 0",
                        },
                        "1 makes static and dynamic friction equal",
                    ),
                },
                None => {
                    b.not_for(
                        s.static_friction_scale.is_some(),
                        span_of(&s.static_friction_scale),
                        "environment.seabed.static_friction_scale",
                        "the tanh friction law",
                        "MoorDyn's friction law, with `friction_damping`",
                    );
                    FrictionLaw::Tanh
                }
            },
        };
        if e.depth.is_none() {
            let span = key_span(b.source, &["environment", "seabed"]);
            let d = b
                .diag(
                    span,
                    "environment.depth",
                    "a seabed is given but no `environment.depth`",
                )
                .value("")
                .expected("m, > 0 (the seabed is at z = −depth)")
                .hint("set `depth` in [environment], or remove the seabed for deep water");
            b.push(d);
        }
    }
    if let Some(c) = &e.current {
        match c.kind.get_ref() {
            CurrentKind::Uniform => {
                b.not_for(
                    c.profile.is_some(),
                    span_of(&c.profile),
                    "environment.current.profile",
                    "a uniform current",
                    "`type = \"profile\"`",
                );
                match &c.velocity {
                    Some(v) => {
                        env.current = Current::Uniform(b.vec3(v, "environment.current.velocity"))
                    }
                    None => {
                        let d = b
                            .diag(
                                Some(c.kind.span()),
                                "environment.current.velocity",
                                "a uniform current needs `velocity`",
                            )
                            .expected("[ux, uy, uz] in m/s");
                        b.push(d);
                    }
                }
            }
            CurrentKind::Profile => {
                b.not_for(
                    c.velocity.is_some(),
                    span_of(&c.velocity),
                    "environment.current.velocity",
                    "a current profile",
                    "`type = \"uniform\"`",
                );
                match &c.profile {
                    Some(p) => {
                        let rows = p.get_ref();
                        let increasing = rows.windows(2).all(|w| w[1][0] > w[0][0]);
                        if rows.is_empty()
                            || !increasing
                            || rows.iter().flatten().any(|x| !x.is_finite())
                        {
                            let d = b
                                .diag(Some(p.span()), "environment.current.profile", "the current profile must have rows with strictly increasing z")
                                .expected("rows [z, ux, uy, uz] in m and m/s, z increasing")
                                .hint("list the deepest point first, e.g. [[-100, 0, 0, 0], [0, 0.5, 0, 0]]");
                            b.push(d);
                        } else {
                            env.current = Current::Profile {
                                z: rows.iter().map(|r| r[0]).collect(),
                                velocity: rows
                                    .iter()
                                    .map(|r| Vec3::new(r[1], r[2], r[3]))
                                    .collect(),
                            };
                        }
                    }
                    None => {
                        let d = b
                            .diag(
                                Some(c.kind.span()),
                                "environment.current.profile",
                                "a current profile needs `profile`",
                            )
                            .expected("rows [z, ux, uy, uz] in m and m/s");
                        b.push(d);
                    }
                }
            }
            CurrentKind::ProfileTable => {
                if let Some(table) = sea::current_table(b, c) {
                    env.current = table;
                }
            }
        }
    }
    if let Some(w) = &e.waves {
        env.waves = build_waves(b, w, env.depth, env.gravity);
        env.wave_kinematics = sea::wave_kinematics(b, w, &env.waves);
    }
    env
}

/// A required number of `[environment.waves]` for the wave type at `kind`.
fn wave_value(
    b: &mut Builder,
    v: &Option<Spanned<f64>>,
    kind: &Spanned<WaveKind>,
    name: &str,
    check: Check,
    hint: &str,
) -> f64 {
    let key = format!("environment.waves.{name}");
    match v {
        Some(v) => b.num(v, &key, check, hint),
        None => {
            let what = match kind.get_ref() {
                WaveKind::Regular => "a regular wave",
                WaveKind::Jonswap => "a JONSWAP sea",
                WaveKind::PiersonMoskowitz => "a Pierson–Moskowitz sea",
                WaveKind::ElevationRecord => "an elevation record",
            };
            let d = b
                .diag(Some(kind.span()), &key, format!("{what} needs `{name}`"))
                .value("")
                .expected(check.expected)
                .hint(hint);
            b.push(d);
            1.0
        }
    }
}

/// `[environment.waves]` into [`Waves`] for water of `depth` [m] under `gravity` [m/s²].
fn build_waves(b: &mut Builder, w: &WavesSpec, depth: f64, gravity: f64) -> Waves {
    use std::f64::consts::PI;
    let errors = b.errors.len();
    let kind = *w.kind.get_ref();
    let regular_keys = [
        ("height", span_of(&w.height)),
        ("period", span_of(&w.period)),
    ];
    let irregular_keys = [
        ("significant_height", span_of(&w.significant_height)),
        ("peak_period", span_of(&w.peak_period)),
        ("gamma", span_of(&w.gamma)),
        ("spreading", span_of(&w.spreading)),
        ("seed", span_of(&w.seed)),
        ("components", span_of(&w.components)),
        ("frequency_range", span_of(&w.frequency_range)),
    ];
    let (misplaced, kind_name, applies): (&[_], _, _) = match kind {
        WaveKind::Regular => (
            &irregular_keys,
            "a regular wave",
            "irregular seas, `type = \"jonswap\"` or `\"pierson-moskowitz\"`",
        ),
        WaveKind::ElevationRecord => (&[], "", ""),
        _ => (&regular_keys, "an irregular sea", "`type = \"regular\"`"),
    };
    if kind != WaveKind::ElevationRecord {
        for (name, span) in sea::record_keys(w) {
            b.not_for(
                span.is_some(),
                span,
                &format!("environment.waves.{name}"),
                "a regular wave or a spectral sea",
                "`type = \"elevation-record\"`",
            );
        }
    }
    for (name, span) in misplaced {
        b.not_for(
            span.is_some(),
            span.clone(),
            &format!("environment.waves.{name}"),
            kind_name,
            applies,
        );
    }
    if kind == WaveKind::PiersonMoskowitz {
        b.not_for(
            w.gamma.is_some(),
            span_of(&w.gamma),
            "environment.waves.gamma",
            "a Pierson–Moskowitz sea",
            "`type = \"jonswap\"` (γ = 1 is Pierson–Moskowitz)",
        );
    }
    if !(gravity > 0.0) {
        let d = b
            .diag(
                Some(w.kind.span()),
                "environment.gravity",
                "waves need gravity",
            )
            .value(format!("{gravity}"))
            .expected("m/s², > 0 with [environment.waves]")
            .hint("set `gravity` > 0 (9.80665 on Earth) or remove [environment.waves]");
        b.push(d);
    }
    let direction = b
        .opt(
            &w.direction,
            "environment.waves.direction",
            0.0,
            Check {
                ok: |_| true,
                expected: "deg, finite",
            },
            "the direction the waves travel toward, from +x toward +y",
        )
        .to_radians();
    let (sea, period) = match kind {
        WaveKind::ElevationRecord => match sea::elevation_record(b, w, direction) {
            Some(r) => r,
            None => return Waves::None,
        },
        WaveKind::Regular => {
            let height = wave_value(
                b,
                &w.height,
                &w.kind,
                "height",
                Check {
                    ok: POSITIVE,
                    expected: "m, > 0 (crest to trough)",
                },
                "the height H from crest to trough, e.g. `height = 2.0`",
            );
            let period = wave_value(
                b,
                &w.period,
                &w.kind,
                "period",
                Check {
                    ok: POSITIVE,
                    expected: "s, > 0",
                },
                "the wave period T, e.g. `period = 8.0`",
            );
            if b.errors.len() == errors
                && let Some(h) = &w.height
            {
                // Miche's limit: a steeper wave breaks.
                let k = wavenumber(2.0 * PI / period, depth, gravity);
                let tanh_kh = if depth.is_finite() {
                    (k * depth).tanh()
                } else {
                    1.0
                };
                let limit = 0.142 * 2.0 * PI / k * tanh_kh;
                if height > limit {
                    let d = b
                        .diag(
                            Some(h.span()),
                            "environment.waves.height",
                            format!("a {height} m, {period} s wave breaks in this water"),
                        )
                        .expected(format!(
                            "m, ≤ {limit:.3}: Miche's breaking limit H/L = 0.142 tanh kh \
                             (wavelength L = {:.2} m)",
                            2.0 * PI / k
                        ))
                        .hint("linear (Airy) waves need a lower wave or a longer period");
                    b.push(d);
                }
            }
            (
                SeaState::Regular(RegularWave {
                    height,
                    period,
                    direction,
                }),
                period,
            )
        }
        WaveKind::Jonswap | WaveKind::PiersonMoskowitz => {
            let significant_height = wave_value(
                b,
                &w.significant_height,
                &w.kind,
                "significant_height",
                Check {
                    ok: POSITIVE,
                    expected: "m, > 0",
                },
                "Hs = 4√m0, e.g. `significant_height = 4.0`",
            );
            let peak_period = wave_value(
                b,
                &w.peak_period,
                &w.kind,
                "peak_period",
                Check {
                    ok: POSITIVE,
                    expected: "s, > 0",
                },
                "the period Tp of the spectral peak, e.g. `peak_period = 10.0`",
            );
            let spectrum = if kind == WaveKind::Jonswap {
                Spectrum::Jonswap {
                    significant_height,
                    peak_period,
                    peak_enhancement: b.opt(
                        &w.gamma,
                        "environment.waves.gamma",
                        3.3,
                        Check {
                            ok: |x| x >= 1.0,
                            expected: "-, ≥ 1 (1 gives Pierson–Moskowitz)",
                        },
                        "3.3 is the mean JONSWAP sea; 1–7 is the usual range",
                    ),
                }
            } else {
                Spectrum::PiersonMoskowitz {
                    significant_height,
                    peak_period,
                }
            };
            let spreading = w.spreading.as_ref().map(|s| {
                b.num(
                    s,
                    "environment.waves.spreading",
                    Check {
                        ok: |s| s > 0.0 && s <= MAX_SPREADING,
                        expected: "-, > 0 and ≤ 1000",
                    },
                    "the cos-2s exponent s: 1–20 for wind seas, larger for swell; omit it for a long-crested sea",
                )
            });
            let components = match &w.components {
                Some(n) if !(1..=100_000).contains(n.get_ref()) => {
                    let d = b
                        .diag(
                            Some(n.span()),
                            "environment.waves.components",
                            "the component count is out of range",
                        )
                        .expected("an integer from 1 to 100000")
                        .hint("100–500 components are usual; the default is 200");
                    b.push(d);
                    1
                }
                Some(n) => *n.get_ref() as usize,
                None => 200,
            };
            let fp = 1.0 / peak_period;
            let frequency_range = match &w.frequency_range {
                Some(r) => {
                    let [lo, hi] = *r.get_ref();
                    if !(lo.is_finite() && hi.is_finite() && lo > 0.0 && hi > lo) {
                        let d = b
                            .diag(
                                Some(r.span()),
                                "environment.waves.frequency_range",
                                "the frequency range must be increasing and positive",
                            )
                            .expected("[lowest, highest] in Hz, 0 < lowest < highest")
                            .hint(format!(
                                "the default is [{:.4}, {:.4}] Hz: 0.5 and 5 times 1/Tp",
                                0.5 * fp,
                                5.0 * fp
                            ));
                        b.push(d);
                    }
                    (2.0 * PI * lo, 2.0 * PI * hi)
                }
                None => (2.0 * PI * 0.5 * fp, 2.0 * PI * 5.0 * fp),
            };
            (
                SeaState::Irregular(IrregularSea {
                    spectrum,
                    direction,
                    spreading,
                    seed: w.seed.as_ref().map_or(1, |s| *s.get_ref() as u64),
                    components,
                    frequency_range,
                }),
                peak_period,
            )
        }
    };
    let ramp_time = b.opt(
        &w.ramp_time,
        "environment.waves.ramp_time",
        2.0 * period,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0 (0: no ramp)",
        },
        "the sea builds up from calm over this time; the default is two (peak) periods",
    );
    let stretching = match w.stretching {
        Some(StretchingSpec::Vertical) => Stretching::Vertical,
        Some(StretchingSpec::Wheeler) | None => Stretching::Wheeler,
    };
    if b.errors.len() > errors {
        return Waves::None;
    }
    let spec = WaveSpec {
        sea,
        ramp_time,
        stretching,
    };
    match Waves::new(&spec, depth, gravity) {
        Ok(waves) => waves,
        Err(e) => {
            let d = b.diag(Some(w.kind.span()), "environment.waves", e.to_string());
            b.push(d);
            Waves::None
        }
    }
}

fn build_line_types(
    b: &mut Builder,
    specs: &[LineTypeSpec],
) -> (Vec<LineType>, HashMap<String, usize>) {
    let mut out = Vec::new();
    let mut index = HashMap::new();
    for (i, t) in specs.iter().enumerate() {
        let k = |key: &str| format!("line_types[{i}].{key}");
        let name = t.name.get_ref().clone();
        if let Some(first) = index.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(t.name.span()),
                    &k("name"),
                    format!("line type `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each line type its own name"
                ));
            b.push(d);
        }
        let diameter = b.num(
            &t.diameter,
            &k("diameter"),
            Check {
                ok: POSITIVE,
                expected: "m, > 0",
            },
            "the nominal (hydrodynamic) diameter, e.g. 0.09 for a 90 mm chain's equivalent",
        );
        let mass = b.num(
            &t.mass_per_length,
            &k("mass_per_length"),
            Check {
                ok: POSITIVE,
                expected: "kg/m, > 0",
            },
            "mass per metre of unstretched line in air",
        );
        let stiffness = match (&t.axial_stiffness, &t.tension_strain) {
            (Some(ea), None) => AxialStiffness::Linear(b.num(
                ea,
                &k("axial_stiffness"),
                Check {
                    ok: POSITIVE,
                    expected: "N, > 0 (EA)",
                },
                "EA = Young's modulus × area, e.g. 3.8e8 N",
            )),
            (None, Some(table)) => {
                let rows = table.get_ref();
                let num = |x: f64| match x.abs() >= 1e4 {
                    true => format!("{x:e}"),
                    false => format!("{x}"),
                };
                let problem = if rows.iter().flatten().any(|x| !x.is_finite()) {
                    Some("the tension–strain table has a non-finite number".to_string())
                } else if rows.len() < 2 {
                    Some("the tension–strain table needs at least two rows".to_string())
                } else if rows[0] != [0.0, 0.0] {
                    Some(format!(
                        "the tension–strain table must start at [0, 0], not [{}, {}]",
                        num(rows[0][0]),
                        num(rows[0][1])
                    ))
                } else if let Some(r) = rows.windows(2).position(|w| !(w[1][0] > w[0][0])) {
                    Some(format!(
                        "strain must increase down the tension–strain table: row {} has {} after {}",
                        r + 2,
                        rows[r + 1][0],
                        rows[r][0]
                    ))
                } else if let Some(r) = rows.windows(2).position(|w| w[1][1] < w[0][1]) {
                    Some(format!(
                        "tension must not decrease down the tension–strain table: row {} has {} N after {} N",
                        r + 2,
                        num(rows[r + 1][1]),
                        num(rows[r][1])
                    ))
                } else if !(rows[rows.len() - 1][1] > 0.0) {
                    Some("the tension–strain table never rises above zero tension".to_string())
                } else {
                    None
                };
                if let Some(problem) = problem {
                    let d = b
                        .diag(Some(table.span()), &k("tension_strain"), problem)
                        .expected("rows [strain, tension] in - and N, starting at [0, 0], strain increasing, tension non-decreasing")
                        .hint("e.g. [[0, 0], [0.01, 2e6], [0.02, 5e6]]");
                    b.push(d);
                    AxialStiffness::Linear(1.0)
                } else {
                    AxialStiffness::Table {
                        strain: rows.iter().map(|r| r[0]).collect(),
                        tension: rows.iter().map(|r| r[1]).collect(),
                    }
                }
            }
            (Some(ea), Some(_)) => {
                let d = b
                    .diag(
                        Some(ea.span()),
                        &k("axial_stiffness"),
                        "give either `axial_stiffness` or `tension_strain`, not both",
                    )
                    .expected("`axial_stiffness` in N (EA), or a `tension_strain` table in - and N")
                    .hint("remove one of them");
                b.push(d);
                AxialStiffness::Linear(1.0)
            }
            (None, None) => {
                let d = b
                    .diag(
                        Some(t.name.span()),
                        &k("axial_stiffness"),
                        format!("line type `{name}` has no axial stiffness"),
                    )
                    .expected("`axial_stiffness` in N (EA) or a `tension_strain` table")
                    .hint("add e.g. `axial_stiffness = 3.84e8`");
                b.push(d);
                AxialStiffness::Linear(1.0)
            }
        };
        let damping = match (&t.axial_damping, &t.axial_damping_ratio) {
            (Some(c), None) => AxialDamping::Coefficient(b.num(
                c,
                &k("axial_damping"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·s, ≥ 0",
                },
                "the coefficient c of T = EA ε + c dε/dt",
            )),
            (None, Some(z)) => AxialDamping::Ratio(b.num(
                z,
                &k("axial_damping_ratio"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0 (fraction of critical)",
                },
                "MoorDyn's BA = -ζ; 0.8 is common for chain",
            )),
            (None, None) => AxialDamping::Coefficient(0.0),
            (Some(c), Some(_)) => {
                let d = b
                    .diag(
                        Some(c.span()),
                        &k("axial_damping"),
                        "give either `axial_damping` or `axial_damping_ratio`, not both",
                    )
                    .hint("remove one of them");
                b.push(d);
                AxialDamping::Coefficient(0.0)
            }
        };
        let drag = match (&t.loading_functions, &t.normal_drag, &t.tangential_drag) {
            (Some(lf), None, None) => DragModel::LoadingFunctions {
                normal: LoadingFunction {
                    cos: lf.normal.cos.clone(),
                    sin: lf.normal.sin.clone(),
                },
                tangential: LoadingFunction {
                    cos: lf.tangential.cos.clone(),
                    sin: lf.tangential.sin.clone(),
                },
            },
            (None, Some(n), Some(tg)) => DragModel::Morison {
                normal: b.num(
                    n,
                    &k("normal_drag"),
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0",
                    },
                    "about 1.2 for wire rope, 2.4 for studless chain on d",
                ),
                tangential: b.num(
                    tg,
                    &k("tangential_drag"),
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0 (on the area d per length)",
                    },
                    "a MoorDyn CdAx on π·d becomes π·CdAx here",
                ),
            },
            (Some(_), _, _) => {
                let span = span_of(&t.normal_drag).or(span_of(&t.tangential_drag));
                let d = b
                    .diag(
                        span,
                        &k("normal_drag"),
                        "give drag coefficients or `loading_functions`, not both",
                    )
                    .hint("remove one of them");
                b.push(d);
                DragModel::Morison {
                    normal: 0.0,
                    tangential: 0.0,
                }
            }
            (None, n, _) => {
                let missing = if n.is_none() {
                    "normal_drag"
                } else {
                    "tangential_drag"
                };
                let d = b
                    .diag(Some(t.name.span()), &k(missing), format!("line type `{name}` has no `{missing}`"))
                    .expected("`normal_drag` and `tangential_drag` (dimensionless, on the area d per length), or `loading_functions`")
                    .hint("e.g. `normal_drag = 1.2` and `tangential_drag = 0.02`");
                b.push(d);
                DragModel::Morison {
                    normal: 0.0,
                    tangential: 0.0,
                }
            }
        };
        out.push(LineType {
            name,
            diameter,
            mass_per_length: mass,
            axial_stiffness: stiffness,
            axial_damping: damping,
            compression: t.compression.unwrap_or(false),
            bending_stiffness: b.opt(
                &t.bending_stiffness,
                &k("bending_stiffness"),
                0.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·m², ≥ 0",
                },
                "EI; 0 for a perfectly flexible cable",
            ),
            bending_damping: b.opt(
                &t.bending_damping,
                &k("bending_damping"),
                0.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·m²·s, ≥ 0",
                },
                "0 unless known",
            ),
            drag,
            normal_added_mass: b.opt(
                &t.normal_added_mass,
                &k("normal_added_mass"),
                1.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0",
                },
                "1 for a circular cylinder",
            ),
            tangential_added_mass: b.opt(
                &t.tangential_added_mass,
                &k("tangential_added_mass"),
                0.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0",
                },
                "usually 0",
            ),
        });
    }
    (out, index)
}

fn build_points(
    b: &mut Builder,
    specs: &[PointSpec],
    env: &Environment,
    body_names: &[String],
) -> (Vec<Point>, HashMap<String, usize>) {
    let mut out = Vec::new();
    let mut index = HashMap::new();
    for (i, p) in specs.iter().enumerate() {
        let k = |key: &str| format!("points[{i}].{key}");
        let name = p.name.get_ref().clone();
        if let Some(first) = index.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(p.name.span()),
                    &k("name"),
                    format!("point `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each point its own name"
                ));
            b.push(d);
        }
        b.check_channel_name(&p.name, &k("name"), "point", "buoy.z");
        let kind = *p.kind.get_ref();
        let kind_name = match kind {
            PointKindSpec::Fixed => "a fixed point",
            PointKindSpec::Free => "a free point",
            PointKindSpec::Prescribed => "a prescribed point",
            PointKindSpec::Body => "a point on a body",
        };
        if kind != PointKindSpec::Body
            && let Some(body) = &p.body
        {
            b.not_for(
                true,
                Some(body.span()),
                &k("body"),
                kind_name,
                "points on bodies (`type = \"body\"`)",
            );
        }
        let position = p.position.as_ref().map(|v| b.vec3(v, &k("position")));
        if kind != PointKindSpec::Free {
            for (present, span, key) in [
                (p.mass.is_some(), span_of(&p.mass), "mass"),
                (p.volume.is_some(), span_of(&p.volume), "volume"),
                (p.drag_area.is_some(), span_of(&p.drag_area), "drag_area"),
                (
                    p.added_mass_coefficient.is_some(),
                    span_of(&p.added_mass_coefficient),
                    "added_mass_coefficient",
                ),
                (p.force.is_some(), span_of(&p.force), "force"),
            ] {
                b.not_for(
                    present,
                    span,
                    &k(key),
                    kind_name,
                    "free points (`type = \"free\"`)",
                );
            }
        }
        if kind != PointKindSpec::Prescribed && p.motion.is_some() {
            let span = p.motion.as_ref().map(|m| m.kind.span());
            b.not_for(
                true,
                span,
                &k("motion"),
                kind_name,
                "prescribed points (`type = \"prescribed\"`)",
            );
        }
        let point_kind = match kind {
            PointKindSpec::Fixed => PointKind::Fixed,
            PointKindSpec::Free => PointKind::Free {
                mass: b.opt(
                    &p.mass,
                    &k("mass"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "kg, ≥ 0",
                    },
                    "the point's mass in air",
                ),
                volume: b.opt(
                    &p.volume,
                    &k("volume"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "m³, ≥ 0",
                    },
                    "displaced volume; buoyancy is ρ g V",
                ),
                drag_area: b.opt(
                    &p.drag_area,
                    &k("drag_area"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "m², ≥ 0 (C_d × area)",
                    },
                    "e.g. 0.5 × π r² for a sphere",
                ),
                added_mass_coefficient: b.opt(
                    &p.added_mass_coefficient,
                    &k("added_mass_coefficient"),
                    0.0,
                    Check {
                        ok: NON_NEGATIVE,
                        expected: "-, ≥ 0",
                    },
                    "0.5 for a sphere",
                ),
                force: p
                    .force
                    .as_ref()
                    .map(|f| b.vec3(f, &k("force")))
                    .unwrap_or_else(Vec3::zeros),
            },
            PointKindSpec::Body => {
                let body = match &p.body {
                    Some(name) => match body_names.iter().position(|n| n == name.get_ref()) {
                        Some(i) => i,
                        None => {
                            let hint = match closest(
                                name.get_ref(),
                                body_names.iter().map(String::as_str),
                            ) {
                                Some(c) => format!("did you mean `{c}`?"),
                                None => "define a [[bodies]] table with that name".to_string(),
                            };
                            let d = b
                                .diag(
                                    Some(name.span()),
                                    &k("body"),
                                    format!("body `{}` does not exist", name.get_ref()),
                                )
                                .expected("the name of a [[bodies]] table")
                                .hint(hint);
                            b.push(d);
                            0
                        }
                    },
                    None => {
                        let d = b
                            .diag(
                                Some(p.kind.span()),
                                &k("body"),
                                format!("point `{name}` is on a body but names none"),
                            )
                            .expected("`body = \"NAME\"`, a [[bodies]] name")
                            .hint("and `position` = the offset from the body origin in body axes");
                        b.push(d);
                        0
                    }
                };
                PointKind::Body {
                    body,
                    offset: position.unwrap_or_else(Vec3::zeros),
                }
            }
            PointKindSpec::Prescribed => match &p.motion {
                Some(m) => PointKind::Prescribed(build_motion(b, m, position, &k("motion"), env)),
                None => {
                    let d = b
                        .diag(
                            Some(p.kind.span()),
                            &k("motion"),
                            format!("prescribed point `{name}` has no `motion`"),
                        )
                        .expected(
                            "a `motion` table of type fixed, constant-velocity, sinusoid, \
                             circular-orbit or time-series",
                        )
                        .hint(
                            "add e.g. `motion = { type = \"sinusoid\", amplitude = [2.0, 0.0, \
                             0.0], period = 10.0 }`, or make the point `fixed`",
                        );
                    b.push(d);
                    PointKind::Fixed
                }
            },
        };
        let pos = match (position, &point_kind) {
            // A point on a vessel: `position` is its place on the vessel; it starts where the
            // vessel's motion puts it at t = 0.
            (Some(_), PointKind::Prescribed(m @ Motion::Rigid { .. })) => m.initial_position(),
            (Some(p), _) => p,
            (None, PointKind::Prescribed(m)) => m.initial_position(),
            (None, _) => {
                let d = b
                    .diag(
                        Some(p.name.span()),
                        &k("position"),
                        format!("point `{name}` has no `position`"),
                    )
                    .expected("[x, y, z] in m");
                b.push(d);
                Vec3::zeros()
            }
        };
        if env.depth.is_finite()
            && kind != PointKindSpec::Body
            && pos.z < -env.depth - 1e-9
            && let Some(ps) = &p.position
        {
            let d = b
                .diag(
                    Some(ps.span()),
                    &k("position"),
                    format!("point `{name}` is below the seabed"),
                )
                .expected(format!("z ≥ −depth = {}", -env.depth))
                .hint(
                    "raise the point, or increase `environment.depth`; anchors sit on the \
                         seabed at z = −depth",
                );
            b.push(d);
        }
        out.push(Point {
            name,
            position: pos,
            kind: point_kind,
        });
    }
    (out, index)
}

fn build_motion(
    b: &mut Builder,
    m: &MotionSpec,
    position: Option<Vec3>,
    key: &str,
    env: &Environment,
) -> Motion {
    let k = |x: &str| format!("{key}.{x}");
    let kind = *m.kind.get_ref();
    let centre = position.unwrap_or_else(Vec3::zeros);
    if matches!(
        kind,
        MotionKind::VesselMotion | MotionKind::Manoeuvre | MotionKind::Rao
    ) {
        // The point rides on a vessel: `position` is its place on the vessel.
        if position.is_none() {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("type"),
                    "a point on a vessel needs its `position` on the vessel",
                )
                .expected("`position = [x, y, z]` on the point, in m, in vessel axes from the vessel origin")
                .hint("e.g. `position = [-40.0, 0.0, -2.0]` for a tow point 40 m aft of the origin, 2 m below it");
            b.push(d);
        }
        return Motion::Rigid {
            motion: Box::new(build_rigid_motion(b, m, key, env)),
            offset: centre,
        };
    }
    if position.is_none() && !matches!(kind, MotionKind::TimeSeries) {
        let d = b
            .diag(
                Some(m.kind.span()),
                &k("type"),
                "this motion is relative to the point's `position`, which is missing",
            )
            .expected("`position = [x, y, z]` on the point, in m");
        b.push(d);
    }
    let allowed: &[&str] = match kind {
        MotionKind::Fixed => &[],
        MotionKind::ConstantVelocity => &["velocity"],
        MotionKind::Sinusoid => &["amplitude", "period", "frequency", "phase", "ramp_time"],
        MotionKind::CircularOrbit => &[
            "radius",
            "frequency",
            "period",
            "phase",
            "plane",
            "ramp_time",
        ],
        MotionKind::TimeSeries => &["table", "file"],
        MotionKind::VesselMotion | MotionKind::Manoeuvre | MotionKind::Rao => unreachable!(),
    };
    reject_keys(b, m, key, allowed);
    let required = |b: &mut Builder, name: &str, unit: &str| {
        let d = b
            .diag(
                Some(m.kind.span()),
                &k(name),
                format!("this motion needs `{name}`"),
            )
            .expected(unit.to_string())
            .hint(format!("add `{name} = ...` to the motion table"));
        b.push(d);
    };
    let ramp = b.opt(
        &m.ramp_time,
        &k("ramp_time"),
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "a few periods lets the system build up without a start-up jerk",
    );
    match kind {
        MotionKind::Fixed => Motion::Fixed { position: centre },
        MotionKind::ConstantVelocity => match &m.velocity {
            Some(v) => Motion::ConstantVelocity {
                start: centre,
                velocity: b.vec3(v, &k("velocity")),
            },
            None => {
                required(b, "velocity", "[vx, vy, vz] in m/s");
                Motion::Fixed { position: centre }
            }
        },
        MotionKind::Sinusoid => {
            let amplitude = match &m.amplitude {
                Some(a) => finite3(b, a, &k("amplitude"), "m"),
                None => {
                    required(b, "amplitude", "m, one value or [ax, ay, az]");
                    [0.0; 3]
                }
            };
            let frequency = frequency_of(b, m, &k("frequency"));
            let phase = m
                .phase
                .as_ref()
                .map(|p| finite3(b, p, &k("phase"), "deg"))
                .unwrap_or([0.0; 3]);
            Motion::Sinusoid {
                centre,
                amplitude: Vec3::from(amplitude),
                frequency: Vec3::from(frequency),
                phase: Vec3::from(phase).map(f64::to_radians),
                ramp,
            }
        }
        MotionKind::CircularOrbit => {
            let radius = match &m.radius {
                Some(r) => b.num(
                    r,
                    &k("radius"),
                    Check {
                        ok: POSITIVE,
                        expected: "m, > 0",
                    },
                    "the orbit radius a",
                ),
                None => {
                    required(b, "radius", "m, > 0");
                    1.0
                }
            };
            for (key, v) in [
                ("frequency", &m.frequency),
                ("period", &m.period),
                ("phase", &m.phase),
            ] {
                if let Some(v) = v
                    && matches!(v.get_ref(), ScalarOrVec3::Vector(_))
                {
                    let d = b
                        .diag(
                            Some(v.span()),
                            &k(key),
                            format!("an orbit takes one `{key}`, not one per axis"),
                        )
                        .expected("a single number")
                        .hint(format!("write e.g. `{key} = 0.2`"));
                    b.push(d);
                }
            }
            let f = frequency_of(b, m, &k("frequency"))[0];
            let (e1, e2) = match m.plane.unwrap_or(PlaneSpec::Xz) {
                PlaneSpec::Xy => (Vec3::x(), Vec3::y()),
                PlaneSpec::Xz => (Vec3::x(), Vec3::z()),
                PlaneSpec::Yz => (Vec3::y(), Vec3::z()),
            };
            let phase = m
                .phase
                .as_ref()
                .map(|p| finite3(b, p, &k("phase"), "deg")[0])
                .unwrap_or(0.0)
                .to_radians();
            Motion::CircularOrbit {
                centre,
                radius,
                frequency: f,
                phase,
                e1,
                e2,
                ramp,
            }
        }
        MotionKind::TimeSeries => {
            let rows: Option<(Vec<[f64; 4]>, Option<Range<usize>>)> = match (&m.table, &m.file) {
                (Some(t), None) => Some((t.get_ref().clone(), Some(t.span()))),
                (None, Some(f)) => {
                    let path = b.file.parent().unwrap_or(Path::new(".")).join(f.get_ref());
                    match read_table::<4>(&path, "t, x, y, z") {
                        Ok(rows) => Some((rows, Some(f.span()))),
                        Err(msg) => {
                            let d = b
                                .diag(Some(f.span()), &k("file"), msg)
                                .expected("a CSV file with columns t [s], x, y, z [m]")
                                .hint("the path is relative to the scenario file");
                            b.push(d);
                            None
                        }
                    }
                }
                (Some(t), Some(_)) => {
                    let d = b.diag(
                        Some(t.span()),
                        &k("table"),
                        "give either `table` or `file`, not both",
                    );
                    b.push(d);
                    None
                }
                (None, None) => {
                    required(b, "table", "rows [t, x, y, z] in s and m, or `file`");
                    None
                }
            };
            match rows {
                Some((rows, span)) => {
                    if rows.is_empty()
                        || !rows.windows(2).all(|w| w[1][0] > w[0][0])
                        || rows.iter().flatten().any(|x| !x.is_finite())
                    {
                        let d = b.diag(span, &k("table"), "the time series needs at least one row and strictly increasing times").expected("rows [t, x, y, z] in s and m");
                        b.push(d);
                        Motion::Fixed { position: centre }
                    } else {
                        Motion::TimeSeries {
                            times: rows.iter().map(|r| r[0]).collect(),
                            positions: rows.iter().map(|r| Vec3::new(r[1], r[2], r[3])).collect(),
                        }
                    }
                }
                None => Motion::Fixed { position: centre },
            }
        }
        MotionKind::VesselMotion | MotionKind::Manoeuvre | MotionKind::Rao => unreachable!(),
    }
}

/// The trajectory of a point fixed on a vessel at `on_vessel` (vessel axes, from the vessel
/// origin: its position when the vessel is at rest at the global origin) from the vessel's
/// motion rows [t, x, y, z, roll, pitch, yaw] (s, m, deg): r(t) = X(t) + R(t)·r0 with
/// R = R_z(yaw)·R_y(pitch)·R_x(roll), the rows' times shifted by `time_offset`, each channel
/// interpolated by a not-a-knot cubic spline ([`RigidTimeSeries`]: velocities and
/// accelerations of the point are exact for the interpolated motion). The rows must have
/// finite values and strictly increasing times.
pub fn vessel_point_motion(
    rows: &[[f64; 7]],
    on_vessel: Vec3,
    time_offset: f64,
) -> Result<Motion, hawser::ModelError> {
    Ok(Motion::Rigid {
        motion: Box::new(RigidMotion::TimeSeries(vessel_time_series(
            rows,
            time_offset,
        )?)),
        offset: on_vessel,
    })
}

/// The 6-DOF table of a vessel-motion file's rows [t, x, y, z, roll, pitch, yaw] (s, m, deg),
/// times shifted by `time_offset` [s].
fn vessel_time_series(
    rows: &[[f64; 7]],
    time_offset: f64,
) -> Result<RigidTimeSeries, hawser::ModelError> {
    RigidTimeSeries::new(
        rows.iter().map(|r| r[0] + time_offset).collect(),
        &rows
            .iter()
            .map(|r| Vec3::new(r[1], r[2], r[3]))
            .collect::<Vec<_>>(),
        &rows
            .iter()
            .map(|r| [r[4].to_radians(), r[5].to_radians(), r[6].to_radians()])
            .collect::<Vec<_>>(),
    )
}

/// Every key of a motion table: (name, given, span).
fn motion_keys(m: &MotionSpec) -> [(&'static str, bool, Option<Range<usize>>); 23] {
    [
        ("velocity", m.velocity.is_some(), span_of(&m.velocity)),
        ("amplitude", m.amplitude.is_some(), span_of(&m.amplitude)),
        ("period", m.period.is_some(), span_of(&m.period)),
        ("frequency", m.frequency.is_some(), span_of(&m.frequency)),
        ("phase", m.phase.is_some(), span_of(&m.phase)),
        ("radius", m.radius.is_some(), span_of(&m.radius)),
        ("ramp_time", m.ramp_time.is_some(), span_of(&m.ramp_time)),
        ("plane", m.plane.is_some(), Some(m.kind.span())),
        ("table", m.table.is_some(), span_of(&m.table)),
        ("file", m.file.is_some(), span_of(&m.file)),
        (
            "time_offset",
            m.time_offset.is_some(),
            span_of(&m.time_offset),
        ),
        ("start", m.start.is_some(), span_of(&m.start)),
        ("heading", m.heading.is_some(), span_of(&m.heading)),
        ("speed", m.speed.is_some(), span_of(&m.speed)),
        (
            "speed_knots",
            m.speed_knots.is_some(),
            span_of(&m.speed_knots),
        ),
        (
            "straight_before",
            m.straight_before.is_some(),
            span_of(&m.straight_before),
        ),
        (
            "turn_radius",
            m.turn_radius.is_some(),
            span_of(&m.turn_radius),
        ),
        ("turn_angle", m.turn_angle.is_some(), span_of(&m.turn_angle)),
        (
            "straight_after",
            m.straight_after.is_some(),
            span_of(&m.straight_after),
        ),
        (
            "build_up_time",
            m.build_up_time.is_some(),
            span_of(&m.build_up_time),
        ),
        (
            "transition_length",
            m.transition_length.is_some(),
            span_of(&m.transition_length),
        ),
        (
            "mean",
            m.mean.is_some(),
            m.mean.as_ref().map(|x| x.kind.span()),
        ),
        ("type", true, Some(m.kind.span())),
    ]
}

/// Reports every key of motion table `m` (at `key`) that its type does not take.
fn reject_keys(b: &mut Builder, m: &MotionSpec, key: &str, allowed: &[&str]) {
    let kind = *m.kind.get_ref();
    for (name, is, span) in motion_keys(m) {
        if is && name != "type" && !allowed.contains(&name) {
            let d = b
                .diag(
                    span,
                    &format!("{key}.{name}"),
                    format!(
                        "`{name}` does not apply to a `{}` motion",
                        motion_name(kind)
                    ),
                )
                .hint(format!(
                    "this motion takes: {}",
                    if allowed.is_empty() {
                        "no parameters".into()
                    } else {
                        allowed.join(", ")
                    }
                ));
            b.push(d);
        }
    }
}

/// One knot in m/s.
const KNOT: f64 = 1852.0 / 3600.0;

/// The rigid-body motion of a vessel (or a prescribed body) from motion table `m` at `key`:
/// `fixed` and `constant-velocity` (the vessel origin at `start`, default the global origin,
/// with `heading`, default 0), `manoeuvre`, `vessel-motion` (6-DOF file) and `rao` (RAO table
/// file on a `mean` motion, driven by `env`'s waves). Every problem is collected in `b`;
/// after an error the returned motion is a harmless placeholder. Reused by `[bodies.motion]`.
fn build_rigid_motion(
    b: &mut Builder,
    m: &MotionSpec,
    key: &str,
    env: &Environment,
) -> RigidMotion {
    let k = |x: &str| format!("{key}.{x}");
    let kind = *m.kind.get_ref();
    let allowed: &[&str] = match kind {
        MotionKind::Fixed => &["start", "heading"],
        MotionKind::ConstantVelocity => &["start", "heading", "velocity"],
        MotionKind::Manoeuvre => &[
            "start",
            "heading",
            "speed",
            "speed_knots",
            "straight_before",
            "turn_radius",
            "turn_angle",
            "straight_after",
            "build_up_time",
            "transition_length",
        ],
        MotionKind::VesselMotion => &["file", "time_offset"],
        MotionKind::Rao => &["file", "mean", "start", "heading"],
        MotionKind::Sinusoid | MotionKind::CircularOrbit | MotionKind::TimeSeries => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("type"),
                    format!(
                        "`{}` is a point motion, not a motion of a vessel or body",
                        motion_name(kind)
                    ),
                )
                .expected(
                    "`fixed`, `constant-velocity`, `manoeuvre`, `vessel-motion` or `rao`",
                )
                .hint("a vessel's 6-DOF history can be given with `vessel-motion` (a file of t, x, y, z, roll, pitch, yaw)");
            b.push(d);
            return RigidMotion::Fixed {
                position: Vec3::zeros(),
                orientation: Quat::identity(),
            };
        }
    };
    reject_keys(b, m, key, allowed);
    let start = m
        .start
        .as_ref()
        .map(|v| b.vec3(v, &k("start")))
        .unwrap_or_else(Vec3::zeros);
    let heading = b
        .opt(
            &m.heading,
            &k("heading"),
            0.0,
            Check {
                ok: |_| true,
                expected: "deg, finite",
            },
            "the vessel's heading from +x toward +y",
        )
        .to_radians();
    let orientation = Quat::from_axis_angle(&Vec3::z_axis(), heading);
    let placeholder = RigidMotion::Fixed {
        position: start,
        orientation,
    };
    let required = |b: &mut Builder, name: &str, unit: &str, hint: &str| {
        let d = b
            .diag(
                Some(m.kind.span()),
                &k(name),
                format!("a `{}` motion needs `{name}`", motion_name(kind)),
            )
            .value("")
            .expected(unit.to_string())
            .hint(hint.to_string());
        b.push(d);
    };
    let file_path = |b: &Builder, f: &Spanned<String>| {
        b.file.parent().unwrap_or(Path::new(".")).join(f.get_ref())
    };
    match kind {
        MotionKind::Fixed => placeholder,
        MotionKind::ConstantVelocity => match &m.velocity {
            Some(v) => RigidMotion::ConstantVelocity {
                start,
                orientation,
                velocity: b.vec3(v, &k("velocity")),
            },
            None => {
                required(
                    b,
                    "velocity",
                    "[vx, vy, vz] in m/s",
                    "add `velocity = [vx, vy, vz]`",
                );
                placeholder
            }
        },
        MotionKind::Manoeuvre => build_manoeuvre(b, m, key, start, heading).unwrap_or(placeholder),
        MotionKind::VesselMotion => {
            let offset = b.opt(
                &m.time_offset,
                &k("time_offset"),
                0.0,
                Check {
                    ok: |_| true,
                    expected: "s, finite",
                },
                "added to the file's times",
            );
            let Some(f) = &m.file else {
                required(
                    b,
                    "file",
                    "a file with columns t, x, y, z, roll, pitch, yaw [s, m, deg]",
                    "add `file = \"vessel_motion.txt\"` (relative to the scenario file)",
                );
                return placeholder;
            };
            let rows = match read_table::<7>(&file_path(b, f), "t, x, y, z, roll, pitch, yaw") {
                Ok(rows) => rows,
                Err(msg) => {
                    let d = b
                        .diag(Some(f.span()), &k("file"), msg)
                        .expected("columns t [s], x, y, z [m], roll, pitch, yaw [deg]")
                        .hint("the path is relative to the scenario file");
                    b.push(d);
                    return placeholder;
                }
            };
            match vessel_time_series(&rows, offset) {
                Ok(s) if !rows.is_empty() => RigidMotion::TimeSeries(s),
                _ => {
                    let d = b
                        .diag(
                            Some(f.span()),
                            &k("file"),
                            "the vessel motion needs at least one row and strictly increasing times",
                        )
                        .expected("rows t, x, y, z, roll, pitch, yaw in s, m and deg")
                        .hint("sort the rows by time and remove repeated times");
                    b.push(d);
                    placeholder
                }
            }
        }
        MotionKind::Rao => {
            let mean = match &m.mean {
                Some(mean) => {
                    for (name, v) in [
                        ("start", span_of(&m.start)),
                        ("heading", span_of(&m.heading)),
                    ] {
                        if let Some(span) = v {
                            let d = b
                                .diag(
                                    Some(span),
                                    &k(name),
                                    format!("`{name}` is given both here and by the `mean` motion"),
                                )
                                .hint(format!("give `{name}` in the `mean` table only"));
                            b.push(d);
                        }
                    }
                    if !matches!(
                        mean.kind.get_ref(),
                        MotionKind::Fixed | MotionKind::ConstantVelocity | MotionKind::Manoeuvre
                    ) {
                        let d = b
                            .diag(
                                Some(mean.kind.span()),
                                &k("mean.type"),
                                format!(
                                    "a vessel's mean motion cannot be `{}`",
                                    motion_name(*mean.kind.get_ref())
                                ),
                            )
                            .expected("`fixed`, `constant-velocity` or `manoeuvre`")
                            .hint("the wave-frequency motion comes from the RAOs; the mean motion is the slow one");
                        b.push(d);
                        placeholder.clone()
                    } else {
                        build_rigid_motion(b, mean, &k("mean"), env)
                    }
                }
                None => placeholder.clone(),
            };
            let Some(f) = &m.file else {
                required(
                    b,
                    "file",
                    "an RAO table file (docs/motions.md)",
                    "add `file = \"vessel_raos.csv\"` (relative to the scenario file)",
                );
                return placeholder;
            };
            let table = match read_rao_table(&file_path(b, f)) {
                Ok(t) => t,
                Err(msg) => {
                    let d = b
                        .diag(Some(f.span()), &k("file"), msg)
                        .expected(
                            "a header `period_s` (or `frequency_hz`, `omega_rad_s`), \
                             `heading_deg`, then amplitude and phase of surge, sway, heave \
                             [m/m, deg], roll, pitch, yaw [deg/m, deg]: 14 columns",
                        )
                        .hint("docs/motions.md describes the RAO file; the path is relative to the scenario file");
                    b.push(d);
                    return placeholder;
                }
            };
            match RaoMotion::new(table, &env.waves, mean) {
                Ok(r) => RigidMotion::Rao(Box::new(r)),
                Err(e) => {
                    let d = b.diag(Some(f.span()), &k("file"), e.to_string());
                    b.push(d);
                    placeholder
                }
            }
        }
        MotionKind::Sinusoid | MotionKind::CircularOrbit | MotionKind::TimeSeries => {
            unreachable!()
        }
    }
}

/// The manoeuvre of motion table `m`; `None` after an error.
fn build_manoeuvre(
    b: &mut Builder,
    m: &MotionSpec,
    key: &str,
    start: Vec3,
    heading: f64,
) -> Option<RigidMotion> {
    let k = |x: &str| format!("{key}.{x}");
    let errors = b.errors.len();
    let speed = match (&m.speed, &m.speed_knots) {
        (Some(v), None) => b.num(
            v,
            &k("speed"),
            Check {
                ok: POSITIVE,
                expected: "m/s, > 0",
            },
            "the ship's speed through the water, e.g. 6.17 m/s (12 kn)",
        ),
        (None, Some(v)) => {
            b.num(
                v,
                &k("speed_knots"),
                Check {
                    ok: POSITIVE,
                    expected: "kn, > 0",
                },
                "the ship's speed in knots, e.g. 12",
            ) * KNOT
        }
        (Some(_), Some(v)) => {
            let d = b
                .diag(
                    Some(v.span()),
                    &k("speed_knots"),
                    "give either `speed` [m/s] or `speed_knots` [kn], not both",
                )
                .hint("remove one of them");
            b.push(d);
            1.0
        }
        (None, None) => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("speed"),
                    "a `manoeuvre` motion needs `speed` [m/s] or `speed_knots` [kn]",
                )
                .value("")
                .expected("m/s, > 0 (or `speed_knots` in kn)")
                .hint("add e.g. `speed_knots = 12.0`");
            b.push(d);
            1.0
        }
    };
    let length = |b: &mut Builder, v: &Option<Spanned<f64>>, name: &str, hint: &str| {
        b.opt(
            v,
            &k(name),
            0.0,
            Check {
                ok: NON_NEGATIVE,
                expected: "m, ≥ 0",
            },
            hint,
        )
    };
    let straight_before = length(
        b,
        &m.straight_before,
        "straight_before",
        "the distance run on the initial heading before the turn",
    );
    let transition_length = length(
        b,
        &m.transition_length,
        "transition_length",
        "the distance over which the curvature builds up into the turn, e.g. a ship length",
    );
    let straight_after = m.straight_after.as_ref().map(|v| {
        b.num(
            v,
            &k("straight_after"),
            Check {
                ok: NON_NEGATIVE,
                expected: "m, ≥ 0",
            },
            "the distance run after the turn before the vessel stops; omit it to go on for ever",
        )
    });
    let build_up_time = b.opt(
        &m.build_up_time,
        &k("build_up_time"),
        0.0,
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "a few minutes lets a towed cable stream out without an impulsive start",
    );
    let turn_radius = match &m.turn_radius {
        Some(v) => b.num(
            v,
            &k("turn_radius"),
            Check {
                ok: POSITIVE,
                expected: "m, > 0",
            },
            "a ship's tactical diameter is typically 3–5 ship lengths: the radius is half of it",
        ),
        None => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("turn_radius"),
                    "a `manoeuvre` motion needs `turn_radius`",
                )
                .value("")
                .expected("m, > 0")
                .hint("add e.g. `turn_radius = 250.0`");
            b.push(d);
            1.0
        }
    };
    let turn_angle = match &m.turn_angle {
        Some(v) => b
            .num(
                v,
                &k("turn_angle"),
                Check {
                    ok: |_| true,
                    expected: "deg, finite (positive to port, negative to starboard)",
                },
                "e.g. 270 for a turn to port through 270°, -90 for a quarter turn to starboard",
            )
            .to_radians(),
        None => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    &k("turn_angle"),
                    "a `manoeuvre` motion needs `turn_angle`",
                )
                .value("")
                .expected("deg, positive to port, negative to starboard")
                .hint("add e.g. `turn_angle = 270.0`; 0 for a straight run");
            b.push(d);
            0.0
        }
    };
    if b.errors.len() > errors {
        return None;
    }
    if transition_length > turn_radius * turn_angle.abs() * (1.0 + 1e-12) && turn_angle != 0.0 {
        let d = b
            .diag(
                span_of(&m.transition_length),
                &k("transition_length"),
                "the curvature transitions are longer than the turn",
            )
            .expected(format!(
                "m, ≤ turn_radius × |turn_angle| = {:.1} m",
                turn_radius * turn_angle.abs()
            ))
            .hint("each transition turns the heading by transition_length / (2 turn_radius); shorten them");
        b.push(d);
        return None;
    }
    let spec = ManoeuvreSpec {
        start,
        heading,
        speed,
        straight_before,
        turn_radius,
        turn_angle,
        straight_after,
        build_up_time,
        transition_length,
    };
    match Manoeuvre::new(spec) {
        Ok(man) => Some(RigidMotion::Manoeuvre(Box::new(man))),
        Err(e) => {
            let span = span_of(&m.straight_after).or(Some(m.kind.span()));
            let d = b
                .diag(span, &k("straight_after"), e.to_string())
                .expected(format!(
                    "m, with the whole track ≥ speed × build_up_time = {:.1} m",
                    speed * build_up_time
                ))
                .hint("lengthen `straight_after` or shorten `build_up_time`");
            b.push(d);
            None
        }
    }
}

/// Reads an RAO table (docs/motions.md): `#` comments and blank lines skipped; a header line
/// whose first name is `period_s`, `frequency_hz` or `omega_rad_s` (the unit of the first
/// column), then rows of 14 numbers: wave period, frequency or angular frequency; heading
/// [deg]; amplitude and phase lag of surge, sway, heave [m/m, deg], roll, pitch, yaw [deg/m,
/// deg]. Rows are grouped by the first column in increasing order, each group listing the same
/// headings in increasing order. Errors name the file and line.
pub fn read_rao_table(path: &Path) -> Result<RaoTable, String> {
    use std::f64::consts::TAU;
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let at = |n: usize| format!("{}:{}", path.display(), n + 1);
    let mut unit: Option<&str> = None;
    // (first column value, heading [deg], amplitudes, phases [deg]) in file order.
    let mut groups: Vec<(f64, usize)> = Vec::new(); // (value, line of its first row)
    let mut headings: Vec<f64> = Vec::new();
    let mut group_headings: Vec<f64> = Vec::new();
    let mut amplitudes: Vec<[f64; 6]> = Vec::new();
    let mut phases: Vec<[f64; 6]> = Vec::new();
    let mut last_line = 0;
    let close_group = |groups: &[(f64, usize)],
                       headings: &mut Vec<f64>,
                       group: &mut Vec<f64>|
     -> Result<(), String> {
        if let Some(&(v, line)) = groups.last() {
            if groups.len() == 1 {
                *headings = group.clone();
            } else if group != headings {
                return Err(format!(
                    "{}: the rows for {v} list the headings {group:?} [deg], but the first \
                     group lists {headings:?}: every period or frequency needs the same headings",
                    at(line)
                ));
            }
        }
        group.clear();
        Ok(())
    };
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = line
            .split([',', ';', '\t', ' '])
            .filter(|s| !s.is_empty())
            .collect();
        if unit.is_none() {
            let first = fields.first().copied().unwrap_or("");
            unit = Some(match first {
                "period_s" => "period_s",
                "frequency_hz" => "frequency_hz",
                "omega_rad_s" => "omega_rad_s",
                _ => {
                    return Err(format!(
                        "{}: the header must start with `period_s`, `frequency_hz` or \
                         `omega_rad_s`, found `{first}`",
                        at(n)
                    ));
                }
            });
            if fields.len() != 14 {
                return Err(format!(
                    "{}: the header names {} columns; an RAO table has 14",
                    at(n),
                    fields.len()
                ));
            }
            continue;
        }
        let nums: Vec<f64> = fields
            .iter()
            .map(|s| s.parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| format!("{}: not a number in `{line}`", at(n)))?;
        if nums.len() != 14 {
            return Err(format!(
                "{}: expected 14 columns (first column, heading, then amplitude and phase of \
                 6 DOFs), found {}",
                at(n),
                nums.len()
            ));
        }
        if nums.iter().any(|x| !x.is_finite()) {
            return Err(format!("{}: non-finite number in `{line}`", at(n)));
        }
        if !(nums[0] > 0.0) {
            return Err(format!(
                "{}: the period or frequency must be > 0, found {}",
                at(n),
                nums[0]
            ));
        }
        let mut amp = [0.0; 6];
        let mut phase = [0.0; 6];
        for d in 0..6 {
            amp[d] = nums[2 + 2 * d];
            phase[d] = nums[3 + 2 * d];
            if amp[d] < 0.0 {
                return Err(format!(
                    "{}: negative RAO amplitude {} of {}",
                    at(n),
                    amp[d],
                    ["surge", "sway", "heave", "roll", "pitch", "yaw"][d]
                ));
            }
        }
        match groups.last() {
            Some(&(v, _)) if nums[0] == v => {
                if group_headings.last().is_some_and(|&h| nums[1] <= h) {
                    return Err(format!(
                        "{}: heading {} deg is not above the previous one ({}): list each \
                         group's headings in increasing order",
                        at(n),
                        nums[1],
                        group_headings.last().unwrap()
                    ));
                }
            }
            Some(&(v, _)) if nums[0] < v => {
                return Err(format!(
                    "{}: {} {} comes after {v}: rows must be sorted by increasing {}",
                    at(n),
                    unit.unwrap(),
                    nums[0],
                    unit.unwrap()
                ));
            }
            _ => {
                close_group(&groups, &mut headings, &mut group_headings)?;
                groups.push((nums[0], n));
            }
        }
        group_headings.push(nums[1]);
        amplitudes.push(amp);
        phases.push(phase);
        last_line = n;
    }
    if groups.is_empty() {
        return Err(format!("{}: the RAO table has no rows", path.display()));
    }
    close_group(&groups, &mut headings, &mut group_headings)?;
    // To angular frequency, increasing; rotations to rad/m, phases to rad.
    let nh = headings.len();
    let mut order: Vec<usize> = (0..groups.len()).collect();
    let omega = |v: f64| match unit.unwrap() {
        "period_s" => TAU / v,
        "frequency_hz" => TAU * v,
        _ => v,
    };
    if unit == Some("period_s") {
        order.reverse();
    }
    let frequencies: Vec<f64> = order.iter().map(|&g| omega(groups[g].0)).collect();
    let mut amps = Vec::with_capacity(amplitudes.len());
    let mut lags = Vec::with_capacity(amplitudes.len());
    for &g in &order {
        for j in 0..nh {
            let mut a = amplitudes[g * nh + j];
            for x in &mut a[3..] {
                *x = x.to_radians();
            }
            amps.push(a);
            lags.push(phases[g * nh + j].map(f64::to_radians));
        }
    }
    let heading_rad: Vec<f64> = headings.iter().map(|h| h.to_radians()).collect();
    RaoTable::new(frequencies, &heading_rad, &amps, &lags)
        .map_err(|e| format!("{}: {e}", at(last_line)))
}

/// A motion parameter given as one number or one per axis, checked to be finite.
fn finite3(b: &mut Builder, v: &Spanned<ScalarOrVec3>, key: &str, unit: &str) -> [f64; 3] {
    let a = v.get_ref().as_array();
    if a.iter().any(|x| !x.is_finite()) {
        let d = b
            .diag(Some(v.span()), key, format!("`{key}` is not finite"))
            .expected(format!("{unit}, one finite number or [x, y, z]"))
            .hint("nan and inf are not allowed here");
        b.push(d);
        return [0.0; 3];
    }
    a
}

/// The name of a motion kind as written in scenario files.
fn motion_name(kind: MotionKind) -> &'static str {
    match kind {
        MotionKind::Fixed => "fixed",
        MotionKind::ConstantVelocity => "constant-velocity",
        MotionKind::Sinusoid => "sinusoid",
        MotionKind::CircularOrbit => "circular-orbit",
        MotionKind::TimeSeries => "time-series",
        MotionKind::VesselMotion => "vessel-motion",
        MotionKind::Manoeuvre => "manoeuvre",
        MotionKind::Rao => "rao",
    }
}

fn frequency_of(b: &mut Builder, m: &MotionSpec, key: &str) -> [f64; 3] {
    match (&m.frequency, &m.period) {
        (Some(f), None) => {
            let f3 = f.get_ref().as_array();
            if f3.iter().any(|x| !(x.is_finite() && *x >= 0.0)) {
                let d = b
                    .diag(Some(f.span()), key, "frequency must be ≥ 0")
                    .expected("Hz, ≥ 0");
                b.push(d);
            }
            f3
        }
        (None, Some(p)) => {
            let p3 = p.get_ref().as_array();
            if p3.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
                let d = b
                    .diag(
                        Some(p.span()),
                        &key.replace("frequency", "period"),
                        "period must be > 0",
                    )
                    .expected("s, > 0");
                b.push(d);
                return [0.0; 3];
            }
            p3.map(|p| 1.0 / p)
        }
        (Some(f), Some(_)) => {
            let d = b.diag(
                Some(f.span()),
                key,
                "give either `frequency` or `period`, not both",
            );
            b.push(d);
            [0.0; 3]
        }
        (None, None) => {
            let d = b
                .diag(
                    Some(m.kind.span()),
                    key,
                    "this motion needs `frequency` [Hz] or `period` [s]",
                )
                .expected("`frequency` in Hz, ≥ 0, or `period` in s, > 0")
                .hint("add e.g. `period = 10.0` to the motion table");
            b.push(d);
            [0.0; 3]
        }
    }
}

/// Reads a table of N numbers per row from a text file: columns separated by commas,
/// semicolons, tabs or spaces; blank lines, `#` comments and one header line are skipped.
/// `columns` names the columns for error messages.
pub fn read_table<const N: usize>(path: &Path, columns: &str) -> Result<Vec<[f64; N]>, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = line
            .split([',', ';', '\t', ' '])
            .filter(|s| !s.is_empty())
            .collect();
        let nums: Result<Vec<f64>, _> = fields.iter().map(|s| s.parse::<f64>()).collect();
        match nums {
            Ok(v) if v.len() == N => {
                let mut row = [0.0; N];
                row.copy_from_slice(&v);
                if row.iter().any(|x| !x.is_finite()) {
                    return Err(format!(
                        "{}:{}: non-finite number in `{line}`",
                        path.display(),
                        n + 1
                    ));
                }
                rows.push(row);
            }
            Ok(v) => {
                return Err(format!(
                    "{}:{}: expected {N} columns ({columns}), found {}",
                    path.display(),
                    n + 1,
                    v.len()
                ));
            }
            Err(_) if rows.is_empty() && n == 0 => continue, // header
            Err(_) => {
                return Err(format!(
                    "{}:{}: not a number in `{line}`",
                    path.display(),
                    n + 1
                ));
            }
        }
    }
    Ok(rows)
}

fn build_lines(
    b: &mut Builder,
    specs: &[LineSpec],
    types: &HashMap<String, usize>,
    points: &HashMap<String, usize>,
) -> Vec<Line> {
    let mut out = Vec::new();
    let mut names = HashMap::new();
    for (i, l) in specs.iter().enumerate() {
        let k = |key: &str| format!("lines[{i}].{key}");
        let name = l.name.get_ref().clone();
        if let Some(first) = names.insert(name.clone(), i) {
            let line = b.line_of(specs[first].name.span());
            let d = b
                .diag(
                    Some(l.name.span()),
                    &k("name"),
                    format!("line `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each line its own name"
                ));
            b.push(d);
        }
        b.check_channel_name(&l.name, &k("name"), "line", "L1.end_b.tension");
        let end = |b: &mut Builder, s: &Spanned<String>, key: &str| -> usize {
            match points.get(s.get_ref()) {
                Some(&p) => p,
                None => {
                    let mut defined: Vec<&str> = points.keys().map(String::as_str).collect();
                    defined.sort();
                    let hint = match closest(s.get_ref(), defined.iter().copied()) {
                        Some(c) => format!("did you mean `{c}`?"),
                        None => format!(
                            "define a [[points]] table with `name = \"{}\"`, or correct the name",
                            s.get_ref()
                        ),
                    };
                    let expected = if defined.is_empty() {
                        "the name of a point; no [[points]] are defined".to_string()
                    } else {
                        format!("the name of a point: {}", defined.join(", "))
                    };
                    let d = b
                        .diag(
                            Some(s.span()),
                            &k(key),
                            format!(
                                "line `{}` is attached to point `{}`, which does not exist",
                                l.name.get_ref(),
                                s.get_ref()
                            ),
                        )
                        .expected(expected)
                        .hint(hint);
                    b.push(d);
                    0
                }
            }
        };
        let end_a = end(b, &l.end_a, "end_a");
        let end_b = end(b, &l.end_b, "end_b");
        if l.end_a.get_ref() == l.end_b.get_ref() {
            let d = b
                .diag(
                    Some(l.end_b.span()),
                    &k("end_b"),
                    "both ends of a line are attached to the same point",
                )
                .hint("attach end B to another point");
            b.push(d);
        }
        let formulation = match l.formulation.as_ref().map(|f| *f.get_ref()) {
            None | Some(FormulationSpec::Fe) => Formulation::Fe,
            Some(FormulationSpec::Hermite) => Formulation::Hermite,
            Some(FormulationSpec::Dg) => Formulation::Dg,
        };
        let mut sections = Vec::new();
        let mut section = |b: &mut Builder,
                           t: &Spanned<String>,
                           length: &Spanned<f64>,
                           elements: &Spanned<i64>,
                           order: &Option<Spanned<i64>>,
                           key: &dyn Fn(&str) -> String| {
            let ti = match types.get(t.get_ref()) {
                Some(&ti) => ti,
                None => {
                    let mut defined: Vec<&str> = types.keys().map(String::as_str).collect();
                    defined.sort();
                    let hint = match closest(t.get_ref(), defined.iter().copied()) {
                        Some(c) => format!("did you mean `{c}`?"),
                        None => format!(
                            "define a [[line_types]] table with `name = \"{}\"`, or correct the name",
                            t.get_ref()
                        ),
                    };
                    let expected = if defined.is_empty() {
                        "the name of a line type; no [[line_types]] are defined".to_string()
                    } else {
                        format!("the name of a line type: {}", defined.join(", "))
                    };
                    let d = b
                        .diag(
                            Some(t.span()),
                            &key("type"),
                            format!("line type `{}` does not exist", t.get_ref()),
                        )
                        .expected(expected)
                        .hint(hint);
                    b.push(d);
                    0
                }
            };
            let len = b.num(
                length,
                &key("length"),
                Check {
                    ok: POSITIVE,
                    expected: "m, > 0 (unstretched)",
                },
                "the unstretched length of this section",
            );
            let n = *elements.get_ref();
            if !(1..=1_000_000).contains(&n) {
                let d = b
                    .diag(
                        Some(elements.span()),
                        &key("elements"),
                        "the element count is out of range",
                    )
                    .expected("an integer from 1 to 1000000")
                    .hint("10–100 elements per line is usual");
                b.push(d);
            }
            let max = hawser::formulation::dg::basis::MAX_ORDER as i64;
            let order = match order {
                None => DEFAULT_DG_ORDER,
                Some(o) if formulation != Formulation::Dg => {
                    let d = b
                        .diag(
                            Some(o.span()),
                            &key("order"),
                            "`order` applies to `dg` lines only",
                        )
                        .expected("no `order` on an `fe` or `hermite` line")
                        .hint("set `formulation = \"dg\"` on the line, or remove `order`");
                    b.push(d);
                    DEFAULT_DG_ORDER
                }
                Some(o) => {
                    if !(1..=max).contains(o.get_ref()) {
                        let d = b
                            .diag(
                                Some(o.span()),
                                &key("order"),
                                "the polynomial order is out of range",
                            )
                            .expected(format!("an integer from 1 to {max}"))
                            .hint("the DG paper uses P = 4; P = 2–6 is usual, cost grows like P²");
                        b.push(d);
                    }
                    (*o.get_ref()).clamp(1, max) as usize
                }
            };
            sections.push(Section {
                line_type: ti,
                length: len,
                elements: n.clamp(1, 1_000_000) as usize,
                order,
            });
        };
        match (&l.line_type, &l.length, &l.elements, l.sections.is_empty()) {
            (Some(t), Some(len), Some(n), true) => section(b, t, len, n, &l.order, &k),
            (None, None, None, false) => {
                for (j, s) in l.sections.iter().enumerate() {
                    let key = |x: &str| format!("lines[{i}].sections[{j}].{x}");
                    section(b, &s.line_type, &s.length, &s.elements, &s.order, &key);
                }
            }
            (None, None, None, true) => {
                let d = b
                    .diag(Some(l.name.span()), &k("sections"), format!("line `{name}` has no sections"))
                    .expected("`type`, `length` [m] and `elements` on the line, or [[lines.sections]] tables")
                    .hint("add e.g. `type = \"chain\"`, `length = 900.0`, `elements = 20`");
                b.push(d);
            }
            (_, _, _, false) => {
                let d = b
                    .diag(
                        Some(l.name.span()),
                        &k("sections"),
                        "give either `type`/`length`/`elements` or [[lines.sections]], not both",
                    )
                    .hint("use sections for lines of several types");
                b.push(d);
            }
            (t, len, n, true) => {
                let missing: Vec<&str> = [
                    ("type", t.is_none()),
                    ("length", len.is_none()),
                    ("elements", n.is_none()),
                ]
                .iter()
                .filter(|x| x.1)
                .map(|x| x.0)
                .collect();
                let d = b
                    .diag(
                        Some(l.name.span()),
                        &k(missing[0]),
                        format!(
                            "line `{name}` is missing {}",
                            missing
                                .iter()
                                .map(|m| format!("`{m}`"))
                                .collect::<Vec<_>>()
                                .join(", ")
                        ),
                    )
                    .expected("`type` (a line type name), `length` [m] and `elements`");
                b.push(d);
            }
        }
        out.push(Line {
            name,
            sections,
            formulation,
            mass_matrix: match l.mass_matrix {
                Some(MassMatrixSpec::Lumped) => MassMatrix::Lumped,
                _ => MassMatrix::Consistent,
            },
            strain_measure: match l.strain {
                Some(StrainSpec::SmallStrain) => StrainMeasure::SmallStrain,
                _ => StrainMeasure::Exact,
            },
            modal_filter: b.opt(
                &l.modal_filter,
                &k("modal_filter"),
                hawser::formulation::dg::line::DEFAULT_MODAL_FILTER,
                Check {
                    ok: |x| (0.0..=1.0).contains(&x),
                    expected: "-, 0 to 1 (0: no filter)",
                },
                "the default 0.05 keeps slack dg lines from spurious high-mode velocities; \
                 larger values damp more of the motion (docs/dg.md)",
            ),
            shock_filter: b.opt(
                &l.shock_filter,
                &k("shock_filter"),
                0.0,
                Check {
                    ok: |x| (0.0..=1.0).contains(&x),
                    expected: "-, 0 to 1 (0: off)",
                },
                "0.25 settled the peak of an undamped dg snap with the mesh (docs/dg.md)",
            ),
            clamp: [(&l.clamp_a, "clamp_a"), (&l.clamp_b, "clamp_b")].map(|(c, key)| {
                let c = c.as_ref()?;
                let d = b.vec3(c, &k(key));
                let bad = if formulation == Formulation::Fe {
                    Some("a clamped end needs bending: use `formulation = \"hermite\"` or `\"dg\"`")
                } else if !(d.norm() > 0.0) {
                    Some("give the direction of the line's tangent at that end, e.g. [1, 0, 0]")
                } else {
                    None
                };
                if let Some(hint) = bad {
                    let diag = b
                        .diag(
                            Some(c.span()),
                            &k(key),
                            format!("`{key}` cannot be used here"),
                        )
                        .expected("a non-zero direction [-] on a `hermite` or `dg` line")
                        .hint(hint);
                    b.push(diag);
                }
                Some(d)
            }),
            end_a: LineEnd::Point(end_a),
            end_b: LineEnd::Point(end_b),
            winch: None,
        });
        if let Some(w) = &l.winch {
            let line = out.last_mut().expect("just pushed");
            line.winch = winch::build_winch(b, w, &k("winch"), line);
        }
    }
    out
}

fn check_free_points_held(b: &mut Builder, specs: &[PointSpec], lines: &[Line], points: &[Point]) {
    for (i, p) in points.iter().enumerate() {
        if let PointKind::Free { mass, volume, .. } = p.kind {
            let attached = lines
                .iter()
                .any(|l| l.end_a == LineEnd::Point(i) || l.end_b == LineEnd::Point(i));
            if !attached && mass == 0.0 && volume == 0.0 {
                let d = b
                    .diag(
                        Some(specs[i].name.span()),
                        &format!("points[{i}]"),
                        format!("free point `{}` has no mass, no volume and no line", p.name),
                    )
                    .hint("attach a line to it, give it a mass, or remove it");
                b.push(d);
            }
        }
    }
}

/// `[[obstacles]]`: spheres and cylinders, fixed or moving (`[obstacles.motion]` as a
/// point's), with their contact parameters. Names share the channel namespace with lines,
/// points and bodies.
fn build_obstacles(b: &mut Builder, scenario: &Scenario, env: &Environment) -> Vec<Obstacle> {
    let mut out: Vec<Obstacle> = Vec::new();
    for (i, o) in scenario.obstacles.iter().enumerate() {
        let k = |key: &str| format!("obstacles[{i}].{key}");
        let name = o.name.get_ref().clone();
        if let Some(first) = scenario.obstacles[..i]
            .iter()
            .position(|x| x.name.get_ref() == &name)
        {
            let line = b.line_of(scenario.obstacles[first].name.span());
            let d = b
                .diag(
                    Some(o.name.span()),
                    &k("name"),
                    format!("obstacle `{name}` is defined twice"),
                )
                .hint(format!(
                    "`{name}` is first defined on line {line}; give each obstacle its own name"
                ));
            b.push(d);
        }
        b.check_channel_name(&o.name, &k("name"), "obstacle", "drum.force_x");
        let clash = scenario
            .lines
            .iter()
            .map(|l| ("line", &l.name))
            .chain(scenario.points.iter().map(|p| ("point", &p.name)))
            .chain(scenario.bodies.iter().map(|b| ("body", &b.name)))
            .find(|(_, n)| n.get_ref() == &name);
        if let Some((what, other)) = clash {
            let line = b.line_of(other.span());
            let d = b
                .diag(
                    Some(o.name.span()),
                    &k("name"),
                    format!("obstacle `{name}` has the name of a {what}, defined on line {line}"),
                )
                .hint("obstacles, lines, points and bodies share the channel namespace: give them different names");
            b.push(d);
        }
        let shape = *o.shape.get_ref();
        let radius = b.num(
            &o.radius,
            &k("radius"),
            Check {
                ok: POSITIVE,
                expected: "m, > 0",
            },
            "the radius of the sphere or cylinder; the cable's own radius d/2 is added to it",
        );
        let shape = match shape {
            ObstacleShapeSpec::Sphere => {
                for (present, span, key) in [
                    (o.axis.is_some(), span_of(&o.axis), "axis"),
                    (o.length.is_some(), span_of(&o.length), "length"),
                ] {
                    b.not_for(
                        present,
                        span,
                        &k(key),
                        "a sphere",
                        "cylinders (`shape = \"cylinder\"`)",
                    );
                }
                ObstacleShape::Sphere { radius }
            }
            ObstacleShapeSpec::Cylinder => {
                let axis = match &o.axis {
                    Some(a) => {
                        let v = Vec3::from(*a.get_ref());
                        if !(v.iter().all(|x| x.is_finite()) && v.norm() > 0.0) {
                            let d = b
                                .diag(
                                    Some(a.span()),
                                    &k("axis"),
                                    "`axis` must be a non-zero direction",
                                )
                                .expected("[x, y, z], finite and not all zero (normalised)")
                                .hint("e.g. [0, 1, 0] for a horizontal cylinder along y");
                            b.push(d);
                            Vec3::z()
                        } else {
                            v.normalize()
                        }
                    }
                    None => {
                        let d = b
                            .diag(
                                Some(o.shape.span()),
                                &k("axis"),
                                format!("cylinder `{name}` has no `axis`"),
                            )
                            .expected("[x, y, z], the direction of the cylinder's axis")
                            .hint("add e.g. `axis = [0, 0, 1]` for a vertical cylinder");
                        b.push(d);
                        Vec3::z()
                    }
                };
                let length = o.length.as_ref().map(|l| {
                    b.num(
                        l,
                        &k("length"),
                        Check {
                            ok: POSITIVE,
                            expected: "m, > 0",
                        },
                        "the cylinder's length, centred on `position`; omit it for an infinite cylinder",
                    )
                });
                ObstacleShape::Cylinder {
                    radius,
                    axis,
                    length,
                }
            }
        };
        let position = o.position.as_ref().map(|v| b.vec3(v, &k("position")));
        let motion = match (&o.motion, position) {
            (Some(m), _) => build_motion(b, m, position, &k("motion"), env),
            (None, Some(p)) => Motion::Fixed { position: p },
            (None, None) => {
                let d = b
                    .diag(
                        Some(o.name.span()),
                        &k("position"),
                        format!("obstacle `{name}` has no `position`"),
                    )
                    .expected("[x, y, z] in m, the centre")
                    .hint("add `position = [x, y, z]`: the centre, or where its `motion` starts");
                b.push(d);
                Motion::Fixed {
                    position: Vec3::zeros(),
                }
            }
        };
        let stiffness = b.num(
            &o.stiffness,
            &k("stiffness"),
            Check {
                ok: POSITIVE,
                expected: "N/m², > 0 (per unit length of cable)",
            },
            "a cable pressed with N newtons per metre sinks N/stiffness metres in; round an \
             obstacle of radius R under tension T, N ≈ T/R",
        );
        let damping = match (&o.damping_ratio, &o.damping) {
            (Some(_), Some(c)) => {
                let d = b
                    .diag(
                        Some(c.span()),
                        &k("damping"),
                        "give either `damping_ratio` or `damping`, not both",
                    )
                    .hint("`damping_ratio` scales with each cable's mass; `damping` is per unit length of cable");
                b.push(d);
                ObstacleDamping::Ratio(1.0)
            }
            (_, Some(c)) => ObstacleDamping::PerLength(b.num(
                c,
                &k("damping"),
                Check {
                    ok: NON_NEGATIVE,
                    expected: "N·s/m², ≥ 0 (per unit length of cable)",
                },
                "or give `damping_ratio` (1 = critical)",
            )),
            (ratio, None) => ObstacleDamping::Ratio(b.opt(
                ratio,
                &k("damping_ratio"),
                1.0,
                Check {
                    ok: NON_NEGATIVE,
                    expected: "-, ≥ 0 (1 = critical)",
                },
                "use 1 for critical damping",
            )),
        };
        let friction_coefficient = b.opt(
            &o.friction_coefficient,
            &k("friction_coefficient"),
            0.0,
            Check {
                ok: NON_NEGATIVE,
                expected: "-, ≥ 0",
            },
            "steel wire on steel is about 0.1–0.2, fibre rope on steel 0.2–0.3",
        );
        let friction_velocity = b.opt(
            &o.friction_velocity,
            &k("friction_velocity"),
            0.01,
            Check {
                ok: POSITIVE,
                expected: "m/s, > 0",
            },
            "a small speed such as 0.01 m/s",
        );
        out.push(Obstacle {
            name,
            shape,
            motion,
            stiffness,
            damping,
            friction_coefficient,
            friction_velocity,
        });
    }
    out
}

fn build_settings(
    b: &mut Builder,
    spec: Option<&SimulationSpec>,
) -> (Settings, Option<Range<usize>>) {
    let mut s = Settings::default();
    let Some(sim) = spec else { return (s, None) };
    s.duration = b.num(
        &sim.duration,
        "simulation.duration",
        Check {
            ok: NON_NEGATIVE,
            expected: "s, ≥ 0",
        },
        "the simulated time span",
    );
    s.output_interval = b.opt(
        &sim.output_interval,
        "simulation.output_interval",
        0.1,
        Check {
            ok: POSITIVE,
            expected: "s, > 0",
        },
        "e.g. 0.1 s",
    );
    s.safety_factor = b.opt(
        &sim.safety_factor,
        "simulation.safety_factor",
        0.8,
        Check {
            ok: |x| x > 0.0 && x <= 1.0,
            expected: "-, in (0, 1]",
        },
        "0.8 leaves a margin below the stability limit",
    );
    if let Some(si) = &sim.snapshot_interval {
        s.snapshot_interval = Some(b.num(
            si,
            "simulation.snapshot_interval",
            Check {
                ok: POSITIVE,
                expected: "s, > 0",
            },
            "e.g. 1 s",
        ));
    }
    s.scheme = match sim.scheme {
        Some(SchemeSpec::SspRk3) => Scheme::SspRk3,
        Some(SchemeSpec::ThreeLevel) => Scheme::ThreeLevel,
        Some(SchemeSpec::Rk4) | None => Scheme::Rk4,
    };
    s.initial_condition = match sim.initial_condition.as_ref().map(|c| *c.get_ref()) {
        Some(InitialConditionSpec::AsDefined) => InitialCondition::AsDefined,
        Some(InitialConditionSpec::SteadyTow) => InitialCondition::SteadyTow,
        _ => InitialCondition::Statics,
    };
    let mut span = None;
    if let Some(ts) = &sim.time_step {
        span = Some(ts.span());
        match ts.get_ref() {
            TimeStepSpec::Value(dt) if dt.is_finite() && *dt > 0.0 => {
                s.time_step = TimeStep::Fixed(*dt)
            }
            TimeStepSpec::Keyword(k) if k == "auto" => s.time_step = TimeStep::Auto,
            _ => {
                let d = b
                    .diag(
                        Some(ts.span()),
                        "simulation.time_step",
                        "`time_step` must be \"auto\" or a positive number of seconds",
                    )
                    .expected("\"auto\" or s, > 0")
                    .hint("\"auto\" picks the largest stable step");
                b.push(d);
            }
        }
    }
    (s, span)
}

/// `simulation.initial_condition = "steady-tow"`: every prescribed motion one constant
/// horizontal velocity, calm water, no dg lines, no release ([`hawser::model::tow_velocity`]).
fn check_steady_tow(b: &mut Builder, spec: Option<&SimulationSpec>, model: &Model) {
    let Some(ic) = spec.and_then(|s| s.initial_condition.as_ref()) else {
        return;
    };
    if *ic.get_ref() != InitialConditionSpec::SteadyTow || !b.errors.is_empty() {
        return;
    }
    if let Err(hawser::error::ModelError::Invalid { what, why }) =
        hawser::model::tow_velocity(model)
    {
        let d = b
            .diag(
                Some(ic.span()),
                "simulation.initial_condition",
                format!("\"steady-tow\": {what} {why}"),
            )
            .expected(
                "a towing vessel: prescribed points and bodies (and obstacles) that all move at \
                 one constant horizontal velocity [m/s], in calm water",
            )
            .hint(
                "give the vessel a `constant-velocity` motion (or a manoeuvre with \
                 build_up_time = 0), or start from \"statics\" or \"as-defined\"",
            );
        b.push(d);
    }
}

/// `simulation.release`: names of free points held in the initial statics, as point indices.
fn build_release(b: &mut Builder, spec: Option<&SimulationSpec>, model: &Model) -> Vec<usize> {
    let mut out = Vec::new();
    let Some(sim) = spec else { return out };
    for (k, name) in sim.release.iter().enumerate() {
        let key = format!("simulation.release[{k}]");
        let n = name.get_ref();
        let Some(p) = model.point_index(n) else {
            let hint = match closest(n, model.points.iter().map(|p| p.name.as_str())) {
                Some(c) => format!("did you mean `{c}`?"),
                None => "list the names of free points ([[points]] with type = \"free\")".into(),
            };
            let d = b
                .diag(Some(name.span()), &key, format!("no point is named `{n}`"))
                .expected("the name of a free point")
                .hint(hint);
            b.push(d);
            continue;
        };
        if !matches!(model.points[p].kind, PointKind::Free { .. }) {
            let d = b
                .diag(
                    Some(name.span()),
                    &key,
                    format!("point `{n}` is not a free point: only free points can be released"),
                )
                .expected("the name of a free point")
                .hint(
                    "make it `type = \"free\"` (mass 0 at the end of a single dg line makes a \
                     free cable end); the statics hold it at its `position`",
                );
            b.push(d);
            continue;
        }
        if out.contains(&p) {
            let d = b
                .diag(
                    Some(name.span()),
                    &key,
                    format!("point `{n}` is released twice"),
                )
                .expected("each point once")
                .hint("remove the repeated name");
            b.push(d);
            continue;
        }
        out.push(p);
    }
    out
}

fn build_channels(
    b: &mut Builder,
    spec: Option<&SimulationSpec>,
    model: &Model,
) -> Vec<OutputChannel> {
    let mut out = Vec::new();
    for (li, _) in model.lines.iter().enumerate() {
        for end_b in [false, true] {
            out.push(OutputChannel::new(Channel::EndTension { line: li, end_b }));
        }
    }
    // A winch line's length and winch tension.
    for (li, l) in model.lines.iter().enumerate() {
        if l.winch.is_some() {
            out.push(OutputChannel::new(Channel::LineLength { line: li }));
            out.push(OutputChannel::new(Channel::WinchTension { line: li }));
        }
    }
    for (pi, p) in model.points.iter().enumerate() {
        if matches!(p.kind, PointKind::Free { .. }) {
            for axis in 0..3 {
                out.push(OutputChannel::new(Channel::PointPosition {
                    point: pi,
                    axis,
                }));
            }
        }
    }
    for body in 0..model.bodies.len() {
        for dof in 0..6 {
            out.push(OutputChannel::new(Channel::BodyMotion { body, dof }));
        }
    }
    for obstacle in 0..model.environment.obstacles.len() {
        for axis in 0..3 {
            out.push(OutputChannel::new(Channel::ObstacleForce {
                obstacle,
                axis,
            }));
        }
    }
    let Some(sim) = spec else { return out };
    for (ci, c) in sim.channels.iter().enumerate() {
        let (label, spec) = match c.get_ref().split_once('=') {
            Some((l, s)) => (Some(l.trim().to_string()), s.trim()),
            None => (None, c.get_ref().trim()),
        };
        if label
            .as_ref()
            .is_some_and(|l| l.is_empty() || l.contains(','))
        {
            let d = b
                .diag(
                    Some(c.span()),
                    &format!("simulation.channels[{ci}]"),
                    "a column name must be non-empty and free of commas",
                )
                .expected("\"NAME = CHANNEL\", e.g. \"FairTen1 = L1.end_b.node_force\"");
            b.push(d);
            continue;
        }
        match parse_channel(spec, model) {
            Ok(ch) => {
                let o = OutputChannel { channel: ch, label };
                // named channels are always recorded; unnamed repeats are dropped
                if o.label.is_some() || !out.iter().any(|x| x.channel == ch) {
                    out.push(o);
                }
            }
            Err(msg) => {
                let first = spec.split('.').next().unwrap_or("");
                let hint = if let Some(li) = model.line_index(first) {
                    let prefix = format!("lines[{li}].");
                    if b.errors.iter().any(|d| d.key.starts_with(&prefix)) {
                        continue; // the line itself is wrong (e.g. its element count)
                    }
                    let n = model.lines[li].elements();
                    format!(
                        "line `{first}` has nodes node0 (end A) … node{n} (end B) and elements \
                         element0 … element{}, and the channels {first}.length, \
                         {first}.stretched_length, {first}.stretch{}",
                        n.saturating_sub(1),
                        if model.lines[li].winch.is_some() {
                            format!(" and {first}.winch_tension")
                        } else {
                            String::new()
                        }
                    )
                } else if model.point_index(first).is_some() {
                    format!("point `{first}` has channels {first}.x|y|z|vx|vy|vz|fx|fy|fz")
                } else if model.bodies.iter().any(|b| b.name == first) {
                    format!(
                        "body `{first}` has channels {first}.{}, .{} and .{}",
                        hawser::analysis::BODY_MOTION.join("|"),
                        hawser::analysis::BODY_VELOCITY.join("|"),
                        hawser::analysis::BODY_LINE_LOAD.join("|")
                    )
                } else if model.environment.obstacles.iter().any(|o| o.name == first) {
                    format!(
                        "obstacle `{first}` has channels {first}.force_x|force_y|force_z|contact_length"
                    )
                } else {
                    let names = model.lines.iter().map(|l| l.name.as_str());
                    let names = names.chain(model.points.iter().map(|p| p.name.as_str()));
                    let names = names.chain(model.bodies.iter().map(|b| b.name.as_str()));
                    let names =
                        names.chain(model.environment.obstacles.iter().map(|o| o.name.as_str()));
                    match closest(first, names) {
                        Some(c) => format!("did you mean `{c}`?"),
                        None => "a channel starts with the name of a line, a point, a body or an obstacle"
                            .to_string(),
                    }
                };
                let d = b
                    .diag(Some(c.span()), &format!("simulation.channels[{ci}]"), msg)
                    .expected("LINE.end_a|end_b.tension|node_force|fx|fy|fz, LINE.nodeK.tension|x|y|z|vx|vy|vz, LINE.elementK.strain, LINE.length|stretched_length|stretch|winch_tension, POINT.x|y|z|vx|vy|vz|fx|fy|fz, BODY.x|y|z|roll|pitch|yaw|vx|…|wz|fx|…|mz, POINT|BODY.relative_to.POINT|BODY.x|y|z, OBSTACLE.force_x|force_y|force_z|contact_length")
                    .hint(hint);
                b.push(d);
            }
        }
    }
    out
}

/// Parses a channel name against the model.
pub fn parse_channel(name: &str, model: &Model) -> Result<Channel, String> {
    let axis = |s: &str| match s {
        "x" => Some(0),
        "y" => Some(1),
        "z" => Some(2),
        _ => None,
    };
    let parts: Vec<&str> = name.split('.').collect();
    if let Some(li) = model.line_index(parts[0]) {
        let n = model.lines[li].elements();
        match parts.as_slice() {
            [_, "length"] => return Ok(Channel::LineLength { line: li }),
            [_, "stretched_length"] => return Ok(Channel::LineStretchedLength { line: li }),
            [_, "stretch"] => return Ok(Channel::LineStretch { line: li }),
            [_, "winch_tension"] => {
                if model.lines[li].winch.is_none() {
                    return Err(format!(
                        "line `{}` has no winch, so no winch tension",
                        parts[0]
                    ));
                }
                return Ok(Channel::WinchTension { line: li });
            }
            [_, end @ ("end_a" | "end_b"), q] => {
                let end_b = *end == "end_b";
                match *q {
                    "tension" => return Ok(Channel::EndTension { line: li, end_b }),
                    "node_force" => return Ok(Channel::EndNodeForce { line: li, end_b }),
                    f if f.len() == 2 && f.starts_with('f') => {
                        if let Some(a) = axis(&f[1..]) {
                            return Ok(Channel::EndForce {
                                line: li,
                                end_b,
                                axis: a,
                            });
                        }
                    }
                    _ => {}
                }
            }
            [_, node, q] if node.starts_with("node") => {
                let Ok(k) = node[4..].parse::<usize>() else {
                    return Err(format!("`{node}` is not a node (use node0 … node{n})"));
                };
                if k > n {
                    return Err(format!(
                        "line `{}` has nodes 0 … {n}; node {k} does not exist",
                        parts[0]
                    ));
                }
                match *q {
                    "tension" => return Ok(Channel::NodeTension { line: li, node: k }),
                    v if v.len() == 2 && v.starts_with('v') => {
                        if let Some(a) = axis(&v[1..]) {
                            return Ok(Channel::NodeVelocity {
                                line: li,
                                node: k,
                                axis: a,
                            });
                        }
                    }
                    p => {
                        if let Some(a) = axis(p) {
                            return Ok(Channel::NodePosition {
                                line: li,
                                node: k,
                                axis: a,
                            });
                        }
                    }
                }
            }
            [
                _,
                el,
                quantity @ ("strain" | "curvature" | "bending_moment" | "shear_force"),
            ] if el.starts_with("element") => {
                let Ok(k) = el[7..].parse::<usize>() else {
                    return Err(format!("`{el}` is not an element"));
                };
                if k >= n {
                    return Err(format!(
                        "line `{}` has elements 0 … {}; element {k} does not exist",
                        parts[0],
                        n.saturating_sub(1)
                    ));
                }
                let (line, element) = (li, k);
                return Ok(match *quantity {
                    "strain" => Channel::ElementStrain { line, element },
                    "curvature" => Channel::ElementCurvature { line, element },
                    "bending_moment" => Channel::ElementBendingMoment { line, element },
                    _ => Channel::ElementShearForce { line, element },
                });
            }
            _ => {}
        }
        return Err(format!("unknown channel `{name}`"));
    }
    let find_object = |n: &str| {
        model.point_index(n).map(Object::Point).or_else(|| {
            model
                .bodies
                .iter()
                .position(|b| b.name == n)
                .map(Object::Body)
        })
    };
    if let [o, "relative_to", r, q] = parts.as_slice()
        && let Some(object) = find_object(o)
    {
        let Some(reference) = find_object(r) else {
            return Err(format!(
                "`{r}` in `{name}` is no point or body: the reference of a relative position \
                 is a point (global axes) or a body (its axes)"
            ));
        };
        if reference == object {
            return Err(format!(
                "`{name}` is a position relative to itself, always zero"
            ));
        }
        let Some(axis) = axis(q) else {
            return Err(format!("`{q}` in `{name}` is not an axis: use x, y or z"));
        };
        return Ok(Channel::RelativePosition {
            object,
            reference,
            axis,
        });
    }
    if let Some(pi) = model.point_index(parts[0]) {
        if let [_, q] = parts.as_slice() {
            if let Some(a) = axis(q) {
                return Ok(Channel::PointPosition { point: pi, axis: a });
            }
            if q.len() == 2
                && q.starts_with('v')
                && let Some(a) = axis(&q[1..])
            {
                return Ok(Channel::PointVelocity { point: pi, axis: a });
            }
            if q.len() == 2
                && q.starts_with('f')
                && let Some(a) = axis(&q[1..])
            {
                return Ok(Channel::PointForce { point: pi, axis: a });
            }
        }
        return Err(format!("unknown channel `{name}`"));
    }
    if let Some(bi) = model.bodies.iter().position(|b| b.name == parts[0]) {
        if let [_, q] = parts.as_slice() {
            let find = |names: &[&str; 6]| names.iter().position(|n| n == q);
            if let Some(dof) = find(&hawser::analysis::BODY_MOTION) {
                return Ok(Channel::BodyMotion { body: bi, dof });
            }
            if let Some(dof) = find(&hawser::analysis::BODY_VELOCITY) {
                return Ok(Channel::BodyVelocity { body: bi, dof });
            }
            if let Some(dof) = find(&hawser::analysis::BODY_LINE_LOAD) {
                return Ok(Channel::BodyLineLoad { body: bi, dof });
            }
        }
        return Err(format!("unknown channel `{name}`"));
    }
    if let Some(oi) = model
        .environment
        .obstacles
        .iter()
        .position(|o| o.name == parts[0])
    {
        if let [_, q] = parts.as_slice() {
            match *q {
                "force_x" | "force_y" | "force_z" => {
                    let axis = axis(&q[6..]).expect("x, y or z");
                    return Ok(Channel::ObstacleForce { obstacle: oi, axis });
                }
                "contact_length" => return Ok(Channel::ObstacleContactLength { obstacle: oi }),
                _ => {}
            }
        }
        return Err(format!("unknown channel `{name}`"));
    }
    Err(format!(
        "channel `{name}` names no line, point, body or obstacle"
    ))
}
