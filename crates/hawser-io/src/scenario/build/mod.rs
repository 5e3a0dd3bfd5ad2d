//! Validation of a parsed scenario and its conversion into a [`hawser::Model`].
//! Every problem is collected (not just the first) with its file position.

use super::diagnostics::{Diagnostic, LineIndex, ScenarioError};
use super::schema::*;
use hawser::math::Vec3;
use hawser::model::*;
use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;

mod bodies;
mod channels;
mod environment;
mod line_types;
mod lines;
mod motions;
mod obstacles;
mod points;
mod ranges;
mod sea;
mod settings;
mod statistics;
mod toml_errors;
mod winch;
pub use bodies::orientation_from_degrees;
use channels::build_channels;
use environment::build_environment;
use line_types::build_line_types;
use lines::{build_lines, check_free_points_held};
pub use motions::vessel_point_motion;
use motions::{build_motion, build_rigid_motion};
use obstacles::build_obstacles;
use points::build_points;
pub use sea::{read_elevation_file, record_components};
pub use settings::OutputFormats;
use settings::{build_formats, build_release, build_settings, check_steady_tow};
use statistics::build_statistics;
use toml_errors::schema_errors;

/// A scenario read from a file: the model (with its output channels) and where things are.
#[derive(Clone, Debug)]
pub struct LoadedScenario {
    /// The model.
    pub model: Model,
    /// Whether `[simulation]` was given.
    pub has_simulation: bool,
    /// Span of `simulation.time_step`, for step errors.
    pub time_step_span: Option<Range<usize>>,
    /// What the file was.
    pub format: InputFormat,
    /// The window, storm duration and linked columns of the design statistics
    /// (`[statistics]`); linked columns index `model.outputs`.
    pub statistics: hawser::analysis::statistics::StatisticsOptions,
    /// The result formats a run writes besides CSV and JSON.
    pub formats: OutputFormats,
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
    /// Line starts of `source`, to locate every diagnostic in O(log lines).
    lines: LineIndex,
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
    fn new(file: &'a Path, source: &'a str) -> Self {
        Self {
            file,
            source,
            lines: LineIndex::new(source),
            errors: Vec::new(),
        }
    }

    fn diag(
        &self,
        span: Option<Range<usize>>,
        key: &str,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::indexed(self.file, self.source, &self.lines, span, key, message)
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
        } else if n.contains(['/', '\\', ':']) || n.chars().any(char::is_control) {
            // Line names name snapshot files: a separator would write outside the output
            // folder, and a control character makes a file name no tool handles.
            let d = self
                .diag(
                    Some(name.span()),
                    key,
                    format!("{kind} names must not hold `/`, `\\`, `:` or control characters"),
                )
                .hint("they become file names in the output folder (snapshots/NAME.csv)");
            self.push(d);
        }
    }

    fn push(&mut self, d: Diagnostic) {
        self.errors.push(d);
    }

    /// 1-based line of a byte offset, for "first defined on line N" hints.
    fn line_of(&self, span: Range<usize>) -> usize {
        self.lines.line(span.start)
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
        if !self.physical(Some(v.span()), key, &[x]) {
            return 1.0;
        }
        x
    }

    /// Checks finite `values` of `key` (written at `span`) against the key's physical range
    /// ([`ranges`]); reports the first one outside it. Whether all are inside.
    fn physical(&mut self, span: Option<Range<usize>>, key: &str, values: &[f64]) -> bool {
        let Some(range) = ranges::range_of(key) else {
            return true;
        };
        let outside = values.iter().enumerate().find(|&(j, &x)| {
            let b = range.bounds(j);
            x.is_finite() && !(b.min <= x && x <= b.max)
        });
        let Some((j, &x)) = outside else {
            return true;
        };
        let bounds = range.bounds(j);
        let message = match values.len() {
            1 => format!("`{key}` is outside its physical range"),
            _ => format!(
                "`{key}` has {} (entry {j}) outside its physical range",
                ranges::number(x)
            ),
        };
        let d = self
            .diag(span, key, message)
            .expected(format!(
                "{}, from {} to {}",
                bounds.unit,
                ranges::number(bounds.min),
                ranges::number(bounds.max)
            ))
            .hint(
                "no physical system comes near this bound: check the unit and the exponent \
                 (values beyond it would overflow the computation)",
            );
        self.push(d);
        false
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
        } else {
            self.physical(Some(v.span()), key, a);
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
    build_with_duration(file, source, None)
}

/// [`build`] with `simulation.duration` replaced by `duration` [s] when given (the command
/// line's `--duration`), validated as the key itself; the value is placed at the start of the
/// file, where an error about it then points.
pub fn build_with_duration(
    file: &Path,
    source: &str,
    duration: Option<f64>,
) -> Result<LoadedScenario, ScenarioError> {
    let mut scenario: Scenario =
        toml::from_str(source).map_err(|e| schema_errors(file, source, &e))?;
    if let (Some(d), Some(sim)) = (duration, scenario.simulation.as_mut()) {
        sim.duration = toml::Spanned::new(0..0, d);
    }
    build_scenario(file, source, &scenario)
}

/// Validates a scenario whose values carry spans into `source` (the text of `file`: the TOML
/// file itself, or a MoorDyn deck the scenario was converted from).
pub fn build_scenario(
    file: &Path,
    source: &str,
    scenario: &Scenario,
) -> Result<LoadedScenario, ScenarioError> {
    let mut b = Builder::new(file, source);
    let environment = build_environment(&mut b, scenario.environment.as_ref());
    let (line_types, type_index) = build_line_types(&mut b, &scenario.line_types);
    let body_names: Vec<String> = scenario
        .bodies
        .iter()
        .map(|s| s.name.get_ref().clone())
        .collect();
    let (points, point_index) = build_points(&mut b, &scenario.points, &environment, &body_names);
    let (lines, mut failures) = build_lines(
        &mut b,
        &scenario.lines,
        &type_index,
        &point_index,
        &line_types,
    );
    lines::build_joined_failures(
        &mut b,
        &scenario.failures,
        &lines,
        &point_index,
        &mut failures,
    );
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
    let formats = build_formats(&mut b, scenario.simulation.as_ref());
    let mut model = Model {
        environment,
        line_types,
        lines,
        points,
        bodies,
        settings,
        outputs: Vec::new(),
        failures,
    };
    model.settings.release = build_release(&mut b, scenario.simulation.as_ref(), &model);
    model.outputs = build_channels(&mut b, scenario.simulation.as_ref(), &model);
    let statistics = build_statistics(
        &mut b,
        scenario.statistics.as_ref(),
        scenario.simulation.is_some(),
        &mut model,
    );
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
        has_simulation: scenario.simulation.is_some(),
        time_step_span,
        format: InputFormat::Toml,
        statistics,
        formats,
    })
}

#[cfg(test)]
mod tests {
    use crate::scenario::diagnostics::work;
    use std::path::Path;

    /// A valid scenario, then `n` copies of `bad` (with `{i}` replaced by 0, 1, …).
    fn scenario(n: usize, bad: &str) -> String {
        let mut s = String::from(
            "[[line_types]]\nname = \"chain\"\ndiameter = 0.1\nmass_per_length = 100.0\n\
             axial_stiffness = 1e8\nnormal_drag = 1.2\ntangential_drag = 0.02\n\n[[points]]\nname = \"anchor\"\ntype = \"fixed\"\n\
             position = [0.0, 0.0, -100.0]\n\n[[points]]\nname = \"top\"\ntype = \"fixed\"\n\
             position = [50.0, 0.0, 0.0]\n\n[[lines]]\nname = \"line\"\nend_a = \"anchor\"\n\
             end_b = \"top\"\ntype = \"chain\"\nlength = 120.0\nelements = 10\n",
        );
        for i in 0..n {
            s += &bad.replace("{i}", &i.to_string());
        }
        s
    }

    /// (errors, work counted) of reading `text`.
    fn errors_and_work(text: &str, read: fn(&str) -> Option<usize>) -> (usize, usize) {
        let before = work::done();
        let errors = read(text).expect("rejected");
        (errors, work::done() - before)
    }

    fn toml(text: &str) -> Option<usize> {
        super::build(Path::new("many.toml"), text)
            .err()
            .map(|e| e.diagnostics.len())
    }

    fn deck(text: &str) -> Option<usize> {
        let options = crate::moordyn::ConvertOptions::default();
        crate::moordyn::parse(Path::new("many.dat"), text, &options)
            .err()
            .map(|e| e.diagnostics.len())
    }

    /// Checks that the work of reporting `n` and `2n` errors grows linearly: doubling the
    /// errors (and the file) at most doubles it, with 10 % for the fixed part (quadratic
    /// growth, as when each error scanned the file up to its offset, gives 4×).
    fn assert_linear(what: &str, make: impl Fn(usize) -> String, read: fn(&str) -> Option<usize>) {
        let n = 1000;
        let (e1, w1) = errors_and_work(&make(n), read);
        let (e2, w2) = errors_and_work(&make(2 * n), read);
        assert_eq!((e1, e2), (n, 2 * n), "{what}: one error per bad entry");
        let ratio = w2 as f64 / w1 as f64;
        assert!(
            ratio < 2.2,
            "{what}: work {w1} for {n} errors, {w2} for {}",
            2 * n
        );
        // And per error, no more than a few times the text of its table.
        assert!(w2 < 64 * make(2 * n).len(), "{what}: work {w2}");
    }

    /// Error reporting once grew quadratically with the number of errors (16 000 took 52 s):
    /// each diagnostic scanned the file up to its offset to find its line, and each TOML
    /// error parsed the whole file again to find its key. Both are linear now.
    #[test]
    fn error_reporting_is_linear_in_the_errors() {
        let value = "\n[[points]]\nname = \"p{i}\"\ntype = \"free\"\nposition = [0.0, 0.0, -10.0]\nmass = -1.0\n";
        assert_linear("bad values", |n| scenario(n, value), toml);
        let key = "\n[[points]]\nname = \"p{i}\"\ntype = \"fixed\"\nposition = [0.0, 0.0, -10.0]\nmas = 1.0\n";
        assert_linear("unknown keys", |n| scenario(n, key), toml);
        let deck_of = |n: usize| {
            let mut s = String::from(
                "--- MoorDyn ---\n---- LINE TYPES ----\nTypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx\n\
                 (-) (m) (kg/m) (N) (N-s) (N-m^2) (-) (-) (-) (-)\n\
                 main 0.09 77.7 3.8e8 -0.8 0 1.6 1.0 0.1 0.0\n\
                 ---- POINTS ----\nID Type X Y Z Mass Volume CdA Ca\n(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n\
                 1 Fixed 800 0 -320 0 0 0 0\n2 Fixed 0 0 -70 0 0 0 0\n",
            );
            for i in 0..n {
                s += &format!("{} Free 0 0 -10 -1.0 0 0 0\n", i + 3);
            }
            s += "---- LINES ----\nID LineType AttachA AttachB UnstrLen NumSegs LineOutputs\n\
                  (#) (name) (#) (#) (m) (-) (-)\n1 main 1 2 900 20 -\n\
                  ---- OPTIONS ----\n0.002 dtM\n320 WtrDpth\n--- END ---\n";
            s
        };
        assert_linear("deck values", deck_of, deck);
    }

    /// The JSON Schema behind the hints is built once per process, not once per rejected
    /// scenario.
    #[test]
    fn the_schema_is_built_once() {
        let key = "\n[[points]]\nname = \"p{i}\"\ntype = \"fixed\"\nposition = \"here\"\n";
        for n in [1, 3] {
            assert!(toml(&scenario(n, key)).is_some());
        }
        assert_eq!(super::toml_errors::schema_builds_count(), 1);
    }
}
