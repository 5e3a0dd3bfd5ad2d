//! Conversion of a lexed MoorDyn v2 deck into a hawser [`Scenario`], with MoorDyn's
//! conventions turned into hawser's (docs/moordyn.md lists each):
//!
//! - `CdAx` acts on the surface π·d per length in MoorDyn, hawser's tangential drag on d:
//!   C_dt = π·CdAx.
//! - `BA/-zeta` < 0 is a fraction ζ of the critical damping of one segment's axial mode:
//!   hawser's `axial_damping_ratio` with the same definition, c = ζ·l·√(EA·γ0).
//! - `kBot` [Pa/m] and `cBot` [Pa·s/m] act on the contact area d·l in both codes.
//! - MoorDyn's lines are lumped-mass: converted lines use `fe` with the lumped mass matrix.
//! - Coupled and vessel points become prescribed points: fixed, or riding on a vessel whose
//!   motion is read from a file (`--vessel-motion`).
//! - OUTPUTS channels keep their MoorDyn names as column names; `FairTen`/`AnchTen` are the
//!   net force on the end node, as in MoorDyn.
//!
//! Every value keeps the span of the deck word it came from, and the converter remembers
//! which MoorDyn section and column each scenario key came from, so validation errors are
//! reported in the deck's words.

use super::deck::{Deck, Row, Section, SectionKind, Token};
use crate::scenario::diagnostics::LineIndex;
use crate::scenario::schema::*;
use crate::scenario::tables::parse_number;
use crate::scenario::{Diagnostic, ScenarioError};
use std::collections::HashMap;
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

mod bodies;
mod failures;
mod line_types;
mod options;
mod outputs;
mod rods;
mod water;
use bodies::{DeckBody, body_name, convert_bodies, finish_bodies};
use line_types::convert_line_types;
use options::{environment_of, read_options, simulation_of};
use outputs::convert_outputs;
pub use outputs::output_channel;
use rods::{convert_rod_types, convert_rods};

/// Choices a deck does not make (a deck is driven by a host program that owns them).
#[derive(Clone, Debug, Default)]
pub struct ConvertOptions {
    /// Simulated duration [s]; default: to the end of the vessel motion, else 60 s.
    pub duration: Option<f64>,
    /// Vessel motion applied to every coupled point: a file with columns t, x, y, z, roll,
    /// pitch, yaw [s, m, deg] (e.g. MoorDyn's `ZZP1_A1.txt`), its first row at t = 0 (the
    /// convention of MoorDyn's drivers). A relative path is relative to the working directory.
    pub vessel_motion: Option<PathBuf>,
}

/// Something the user should know about a conversion: a convention converted, or a deck
/// entry with no effect in hawser.
#[derive(Clone, Debug, PartialEq)]
pub struct Note {
    /// 1-based deck line (0 when not tied to a line).
    pub line: usize,
    /// The note.
    pub message: String,
}

/// The result of converting a deck.
#[derive(Debug)]
pub struct Conversion {
    /// The equivalent scenario; its spans point into the deck.
    pub scenario: Scenario,
    /// Conversions and ignored entries.
    pub notes: Vec<Note>,
    /// Scenario key prefix → the deck's words for it (`LINE TYPES › main › Diam`).
    key_names: Vec<(String, String)>,
}

impl Conversion {
    /// Rewrites validation errors so they name the deck's sections and columns instead of
    /// scenario keys.
    pub fn in_deck_words(&self, mut e: ScenarioError) -> ScenarioError {
        // Key → words (a key named twice keeps its last words), so that each diagnostic
        // costs a few lookups, not a pass over every key of the deck.
        let names: HashMap<&str, &str> = self
            .key_names
            .iter()
            .map(|(k, w)| (k.as_str(), w.as_str()))
            .collect();
        for d in &mut e.diagnostics {
            // The longest prefix of the key that ends at a `.`, a `[` or the key's end names
            // the most specific column.
            let ends = d
                .key
                .char_indices()
                .filter(|&(_, c)| c == '.' || c == '[')
                .map(|(i, _)| i)
                .chain([d.key.len()]);
            let best = ends
                .filter_map(|i| {
                    #[cfg(test)]
                    crate::scenario::diagnostics::work::add(1);
                    names.get_key_value(&d.key[..i])
                })
                .max_by_key(|(k, _)| k.len())
                .map(|(k, w)| (k.to_string(), w.to_string()));
            if let Some((k, words)) = best {
                let old = d.key.clone();
                d.message = d
                    .message
                    .replace(&format!("`{old}`"), &format!("`{words}`"))
                    .replace(&format!("`{k}`"), &format!("`{words}`"));
                d.key = words.clone();
            }
        }
        e
    }
}

/// The column layouts of MoorDyn-C 2.7 tables (required columns, then optional ones).
const LINE_TYPE_COLUMNS: &[&str] = &[
    "TypeName", "Diam", "Mass/m", "EA", "BA/-zeta", "EI", "Cd", "Ca", "CdAx", "CaAx", "Cl", "dF",
    "cF",
];
const POINT_COLUMNS: &[&str] = &["ID", "Type", "X", "Y", "Z", "Mass", "Volume", "CdA", "Ca"];
/// The older 12-column points table with a constant force.
const POINT_COLUMNS_WITH_FORCE: &[&str] = &[
    "ID", "Type", "X", "Y", "Z", "Mass", "Volume", "FX", "FY", "FZ", "CdA", "Ca",
];
const LINE_COLUMNS: &[&str] = &[
    "ID",
    "LineType",
    "AttachA",
    "AttachB",
    "UnstrLen",
    "NumSegs",
    "LineOutputs",
];

struct Converter<'a> {
    file: &'a Path,
    source: &'a str,
    /// Line starts of `source`, to locate every diagnostic in O(log lines).
    lines: LineIndex,
    errors: Vec<Diagnostic>,
    notes: Vec<Note>,
    key_names: Vec<(String, String)>,
}

fn spanned<T>(t: &Token, v: T) -> Spanned<T> {
    Spanned::new(t.span.clone(), v)
}

impl<'a> Converter<'a> {
    fn diag(
        &self,
        span: Option<Range<usize>>,
        key: &str,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::indexed(self.file, self.source, &self.lines, span, key, message)
    }

    fn note(&mut self, line: usize, message: impl Into<String>) {
        self.notes.push(Note {
            line,
            message: message.into(),
        });
    }

    fn name_key(&mut self, key: String, words: String) {
        self.key_names.push((key, words));
    }

    fn line_of(&self, span: &Range<usize>) -> usize {
        self.lines.line(span.start)
    }

    /// A number from a table cell, or an error naming the section and column.
    fn number(&mut self, t: &Token, section: &str, column: &str, unit: &str) -> Option<f64> {
        match parse_number(&t.text) {
            Some(x) => Some(x),
            None => {
                let d = self
                    .diag(
                        Some(t.span.clone()),
                        &format!("{section} › {column}"),
                        format!("`{column}` in {section} is not a number"),
                    )
                    .expected(format!("a number in {unit}"))
                    .hint("MoorDyn table cells are numbers such as 0.09, 384.243E6 or -0.8");
                self.errors.push(d);
                None
            }
        }
    }

    /// A whole number from a table cell.
    fn count(&mut self, t: &Token, section: &str, column: &str) -> Option<i64> {
        match t.text.parse::<i64>() {
            Ok(n) => Some(n),
            Err(_) => {
                let d = self
                    .diag(
                        Some(t.span.clone()),
                        &format!("{section} › {column}"),
                        format!("`{column}` in {section} is not a whole number"),
                    )
                    .expected("a whole number such as 20")
                    .hint("segment counts and IDs are integers");
                self.errors.push(d);
                None
            }
        }
    }

    /// Checks a row's column count: at least `required`, at most `columns.len()`.
    fn check_columns(
        &mut self,
        section: &str,
        row: &Row,
        columns: &[&str],
        required: usize,
    ) -> bool {
        let n = row.tokens.len();
        let form = columns.join(" ");
        if n < required {
            let end = row.span.end;
            let d = self
                .diag(
                    Some(end..end),
                    &format!("{section} › {}", columns[n]),
                    format!(
                        "this {section} row has {n} column{}; column `{}` is missing",
                        if n == 1 { "" } else { "s" },
                        columns[n]
                    ),
                )
                .value(self.source[row.span.clone()].trim().to_string())
                .expected(format!(
                    "{} columns: {form}",
                    if required == columns.len() {
                        required.to_string()
                    } else {
                        format!("{required} to {}", columns.len())
                    }
                ))
                .hint(
                    "MoorDyn tables are positional: give every column, separated by spaces or tabs",
                );
            self.errors.push(d);
            return false;
        }
        if n > columns.len() {
            let extra = &row.tokens[columns.len()];
            let d = self
                .diag(
                    Some(extra.span.clone()),
                    &format!("{section} › column {}", columns.len() + 1),
                    format!(
                        "this {section} row has {n} columns; hawser reads {} ({form})",
                        columns.len()
                    ),
                )
                .expected(format!("columns: {form}"))
                .hint(
                    "remove the extra column; if it is a MoorDyn option hawser does not know \
                     (such as VIV coefficients), the deck needs a feature hawser does not have",
                );
            self.errors.push(d);
            return false;
        }
        true
    }

    fn refuse_section(&mut self, s: &Section, what: &str) {
        if s.rows.is_empty() {
            let line = self.line_of(&s.title.span);
            self.note(line, format!("section `{}` is empty", s.title.text));
            return;
        }
        let d = self
            .diag(
                Some(s.title.span.clone()),
                &s.title.text,
                format!("section `{}` is not supported: {what}", s.title.text),
            )
            .value(s.title.text.clone())
            .hint(format!(
                "hawser does not run this section's {} row{}; remove the section to run the rest \
                 of the deck, or model it in a hawser scenario",
                s.rows.len(),
                if s.rows.len() == 1 { "" } else { "s" }
            ));
        self.errors.push(d);
    }
}

/// Converts a lexed deck into a scenario. `file` is the deck's path (for files it names).
pub fn convert(
    file: &Path,
    source: &str,
    deck: &Deck,
    options: &ConvertOptions,
) -> Result<Conversion, ScenarioError> {
    let mut c = Converter {
        file,
        source,
        lines: LineIndex::new(source),
        errors: Vec::new(),
        notes: Vec::new(),
        key_names: Vec::new(),
    };
    let dir = file.parent().unwrap_or(Path::new("."));
    let mut seen: Vec<SectionKind> = Vec::new();
    for s in &deck.sections {
        if s.kind != SectionKind::Unsupported && seen.contains(&s.kind) {
            let d = c
                .diag(
                    Some(s.title.span.clone()),
                    &s.title.text,
                    format!("section `{}` appears twice", s.title.text),
                )
                .hint("merge the two tables into one");
            c.errors.push(d);
        }
        seen.push(s.kind);
        if s.kind == SectionKind::Unsupported {
            c.refuse_section(s, "hawser does not read this section");
        }
    }
    let line_types = match deck.section(SectionKind::LineTypes) {
        Some(s) => convert_line_types(&mut c, s, dir),
        None => Vec::new(),
    };
    let vessel = match options.vessel_motion.as_deref().map(VesselFile::read) {
        Some(Err(d)) => {
            c.errors.push(*d);
            None
        }
        Some(Ok(v)) => Some(v),
        None => None,
    };
    let option_rows = deck
        .section(SectionKind::Options)
        .map(|s| s.rows.as_slice())
        .unwrap_or(&[]);
    let opts = read_options(&mut c, option_rows);
    let rho = opts
        .get(&["rho", "wtrdnsty"])
        .and_then(|(t, _)| parse_number(&t.text))
        .unwrap_or(1025.0);
    let mut deck_bodies = match deck.section(SectionKind::Bodies) {
        Some(s) if s.rows.is_empty() => {
            let line = c.line_of(&s.title.span);
            c.note(line, format!("section `{}` is empty", s.title.text));
            Vec::new()
        }
        Some(s) => convert_bodies(&mut c, s, rho, vessel.as_ref()),
        None => Vec::new(),
    };
    for kind in [SectionKind::RodTypes, SectionKind::Rods] {
        if let Some(s) = deck.section(kind)
            && s.rows.is_empty()
        {
            let line = c.line_of(&s.title.span);
            c.note(line, format!("section `{}` is empty", s.title.text));
        }
    }
    let rod_types = match deck.section(SectionKind::RodTypes) {
        Some(s) => convert_rod_types(&mut c, s),
        None => Default::default(),
    };
    let rod_ends = match deck.section(SectionKind::Rods) {
        Some(s) => convert_rods(&mut c, s, &rod_types, &mut deck_bodies, vessel.as_ref()),
        None => Default::default(),
    };
    let (mut points, coupled) = match deck.section(SectionKind::Points) {
        Some(s) => convert_points(&mut c, s, vessel.as_ref(), &mut deck_bodies),
        None => (Vec::new(), 0),
    };
    points.extend(rod_ends.points);
    let body_kinds: Vec<(String, bool)> = deck_bodies
        .iter()
        .map(|b| (b.name.clone(), b.kind.moves()))
        .collect();
    let bodies = finish_bodies(&mut c, deck_bodies);
    let (mut lines, line_outputs) = match deck.section(SectionKind::Lines) {
        Some(s) => convert_lines(&mut c, s, &points, &rod_ends.refused),
        None => (Vec::new(), false),
    };
    let mut joined_failures = Vec::new();
    if let Some(s) = deck.section(SectionKind::Failure) {
        failures::convert_failures(&mut c, s, &mut lines, &mut joined_failures);
    }
    if deck.section(SectionKind::Lines).is_none() {
        let d = c
            .diag(Some(0..0), "LINES", "the deck has no LINES section")
            .expected("a `---- LINES ----` section with rows ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs")
            .hint("hawser runs decks with at least one line");
        c.errors.push(d);
    }
    let channels = match deck.section(SectionKind::Outputs) {
        Some(s) if !lines.is_empty() => convert_outputs(&mut c, s, &lines, &body_kinds),
        _ => Vec::new(),
    };
    let environment = environment_of(&mut c, &opts, dir, &points);
    let simulation = simulation_of(
        &mut c,
        &opts,
        options.duration,
        vessel.as_ref().and_then(|v| v.duration),
        channels,
        line_outputs,
        coupled,
    );
    if !c.errors.is_empty() {
        c.errors.sort_by_key(|d| (d.line, d.column));
        return Err(ScenarioError {
            diagnostics: c.errors,
        });
    }
    Ok(Conversion {
        scenario: Scenario {
            simulation: Some(simulation),
            environment: Some(environment),
            line_types,
            points,
            lines,
            bodies,
            obstacles: Vec::new(),
            failures: joined_failures,
            statistics: None,
        },
        notes: c.notes,
        key_names: c.key_names,
    })
}

/// A point's name in the scenario: `P` and its MoorDyn ID.
pub(super) fn point_name(id: &str) -> String {
    format!("P{id}")
}

/// A line's name in the scenario: `L` and its MoorDyn ID.
pub(super) fn line_name(id: &str) -> String {
    format!("L{id}")
}

/// The motion of a deck's coupled object run alone: held (`fixed`), or riding on the vessel
/// of `--vessel-motion`; `word` is the deck word (type column) it comes from.
fn rigid_motion_spec(word: &Token, vessel: Option<&VesselFile>) -> MotionSpec {
    MotionSpec {
        kind: spanned(
            word,
            if vessel.is_some() {
                MotionKind::VesselMotion
            } else {
                MotionKind::Fixed
            },
        ),
        velocity: None,
        amplitude: None,
        period: None,
        frequency: None,
        phase: None,
        ramp_time: None,
        radius: None,
        plane: None,
        table: None,
        file: vessel.map(|v| spanned(word, v.path.display().to_string())),
        time_offset: vessel.map(|v| spanned(word, v.time_offset)),
        start: None,
        heading: None,
        speed: None,
        speed_knots: None,
        straight_before: None,
        turn_radius: None,
        turn_angle: None,
        straight_after: None,
        build_up_time: None,
        transition_length: None,
        mean: None,
    }
}

fn convert_points(
    c: &mut Converter,
    s: &Section,
    vessel: Option<&VesselFile>,
    bodies: &mut [DeckBody],
) -> (Vec<PointSpec>, usize) {
    const S: &str = "POINTS";
    let mut out = Vec::new();
    let mut coupled = 0;
    for row in &s.rows {
        let with_force = row.tokens.len() >= POINT_COLUMNS_WITH_FORCE.len();
        let columns = if with_force {
            POINT_COLUMNS_WITH_FORCE
        } else {
            POINT_COLUMNS
        };
        if !c.check_columns(S, row, columns, columns.len()) {
            continue;
        }
        let t = &row.tokens;
        let (force, t) = if with_force {
            let f: Vec<Option<f64>> = ["FX", "FY", "FZ"]
                .iter()
                .zip(&t[7..10])
                .map(|(col, tok)| c.number(tok, &format!("{S} › {}", t[0].text), col, "N"))
                .collect();
            let span = t[7].span.start..t[9].span.end;
            let force = Spanned::new(
                span,
                [
                    f[0].unwrap_or(0.0),
                    f[1].unwrap_or(0.0),
                    f[2].unwrap_or(0.0),
                ],
            );
            let mut rest: Vec<Token> = t[..7].to_vec();
            rest.extend_from_slice(&t[10..]);
            (Some(force), rest)
        } else {
            (None, t.clone())
        };
        let t = &t;
        let i = out.len();
        let name = point_name(&t[0].text);
        let key = |f: &str| format!("points[{i}].{f}");
        for (field, col) in [
            ("name", "ID"),
            ("type", "Type"),
            ("position", "X Y Z"),
            ("mass", "Mass"),
            ("volume", "Volume"),
            ("drag_area", "CdA"),
            ("added_mass_coefficient", "Ca"),
            ("force", "FX FY FZ"),
            ("motion", "Type"),
        ] {
            c.name_key(key(field), format!("{S} › {} › {col}", t[0].text));
        }
        let kind_word = t[1].text.to_lowercase();
        let mut on_body: Option<usize> = None;
        let base = kind_word.trim_end_matches(|ch: char| ch.is_ascii_digit());
        let kind = match base {
            "fixed" | "fix" | "anchor" => Some(PointKindSpec::Fixed),
            "free" | "connect" | "con" | "point" => Some(PointKindSpec::Free),
            "coupled" | "vessel" | "ves" | "cpld" | "fairlead" => Some(PointKindSpec::Prescribed),
            "body" => {
                let number = &kind_word[base.len()..];
                match bodies.iter().position(|b| b.name == body_name(number)) {
                    Some(b) => {
                        on_body = Some(b);
                        Some(PointKindSpec::Body)
                    }
                    None => {
                        let ids: Vec<&str> = bodies
                            .iter()
                            .filter_map(|b| b.name.strip_prefix('B'))
                            .collect();
                        let d = c
                            .diag(
                                Some(t[1].span.clone()),
                                &format!("{S} › {} › Type", t[0].text),
                                format!(
                                    "point {} is on body `{}`, which is not in the BODIES table",
                                    t[0].text, t[1].text
                                ),
                            )
                            .expected(if ids.is_empty() {
                                "a BODIES section with the body".to_string()
                            } else {
                                format!("Body1 … with a body ID: {}", ids.join(", "))
                            })
                            .hint("points on a body are `Body#`, # the body's ID in BODIES");
                        c.errors.push(d);
                        None
                    }
                }
            }
            "turbine" => {
                let d = c
                    .diag(
                        Some(t[1].span.clone()),
                        &format!("{S} › {} › Type", t[0].text),
                        format!("point {} is on a FAST.Farm turbine (`{}`)", t[0].text, t[1].text),
                    )
                    .hint("turbine points are moved by FAST.Farm; make the point `Coupled` to drive it with a vessel motion, or `Fixed`");
                c.errors.push(d);
                None
            }
            _ => {
                let d = c
                    .diag(
                        Some(t[1].span.clone()),
                        &format!("{S} › {} › Type", t[0].text),
                        format!("unknown point type `{}`", t[1].text),
                    )
                    .expected("Fixed (Fix, Anchor), Free (Point, Connect), Coupled (Vessel, Fairlead)")
                    .hint("MoorDyn point types: Fixed (anchor), Free (point mass), Coupled/Vessel (moved by the host)");
                c.errors.push(d);
                None
            }
        };
        let x = c.number(&t[2], &format!("{S} › {}", t[0].text), "X", "m");
        let y = c.number(&t[3], &format!("{S} › {}", t[0].text), "Y", "m");
        let z = c.number(&t[4], &format!("{S} › {}", t[0].text), "Z", "m");
        let mass = c.number(&t[5], &format!("{S} › {}", t[0].text), "Mass", "kg");
        let volume = c.number(&t[6], &format!("{S} › {}", t[0].text), "Volume", "m³");
        let cda = c.number(&t[7], &format!("{S} › {}", t[0].text), "CdA", "m²");
        let ca = c.number(&t[8], &format!("{S} › {}", t[0].text), "Ca", "-");
        let position = spanned(
            &Token {
                text: String::new(),
                span: t[2].span.start..t[4].span.end,
            },
            [x.unwrap_or(0.0), y.unwrap_or(0.0), z.unwrap_or(0.0)],
        );
        let Some(kind) = kind else { continue };
        if let Some(b) = on_body {
            // Its mass and buoyancy are the body's; drag, added mass and a force at a point
            // have no place in a body's loads.
            let body = &mut bodies[b];
            let extra = [(cda, "CdA", &t[7]), (ca, "Ca", &t[8])]
                .into_iter()
                .chain(force.as_ref().map(|f| {
                    let any = f.get_ref().iter().any(|x| *x != 0.0);
                    (any.then_some(1.0), "FX FY FZ", &t[2])
                }))
                .find(|(v, _, _)| v.is_some_and(|x| x != 0.0));
            if body.kind.moves() {
                if let Some((_, col, tok)) = extra {
                    let d = c
                        .diag(
                            Some(tok.span.clone()),
                            &format!("{S} › {} › {col}", t[0].text),
                            format!(
                                "point {} on free body {} has {col}: a point's own drag, added \
                                 mass or force on a body is not modelled",
                                t[0].text, body.name
                            ),
                        )
                        .expected(format!("{col} = 0"))
                        .hint(
                            "give the body its drag and added mass in BODIES (CdA, Ca), and set \
                             the point's to 0",
                        );
                    c.errors.push(d);
                }
                body.fold(bodies::Part {
                    centre: hawser::math::Vec3::new(
                        x.unwrap_or(0.0),
                        y.unwrap_or(0.0),
                        z.unwrap_or(0.0),
                    ),
                    mass: mass.unwrap_or(0.0),
                    inertia: hawser::math::Mat3::zeros(),
                    volume: volume.unwrap_or(0.0),
                });
            } else if extra.is_some() || [mass, volume].iter().any(|v| v.is_some_and(|x| x != 0.0))
            {
                c.note(
                    row.line,
                    format!(
                        "point {}: Mass, Volume, CdA, Ca and force have no effect on a point of \
                         a `{}` body",
                        t[0].text,
                        bodies[b].type_word()
                    ),
                );
            }
            out.push(PointSpec {
                name: spanned(&t[0], name),
                kind: spanned(&t[1], kind),
                position: Some(position),
                mass: None,
                volume: None,
                drag_area: None,
                added_mass_coefficient: None,
                force: None,
                motion: None,
                body: Some(spanned(&t[1], bodies[b].name.clone())),
            });
            continue;
        }
        let free = kind == PointKindSpec::Free;
        let f = |v: Option<f64>, tok: &Token| v.filter(|_| free).map(|x| spanned(tok, x));
        if !free
            && [mass, volume, cda, ca]
                .iter()
                .any(|v| v.is_some_and(|x| x != 0.0))
        {
            c.note(
                row.line,
                format!(
                    "point {}: Mass, Volume, CdA and Ca have no effect on a `{}` point",
                    t[0].text, t[1].text
                ),
            );
        }
        let motion = (kind == PointKindSpec::Prescribed).then(|| {
            coupled += 1;
            let word = Token {
                text: String::new(),
                span: t[1].span.clone(),
            };
            rigid_motion_spec(&word, vessel)
        });
        out.push(PointSpec {
            name: spanned(&t[0], name),
            kind: spanned(&t[1], kind),
            position: Some(position),
            mass: f(mass, &t[5]),
            volume: f(volume, &t[6]),
            drag_area: f(cda, &t[7]),
            added_mass_coefficient: f(ca, &t[8]),
            force: force.filter(|_| free),
            motion,
            body: None,
        });
    }
    (out, coupled)
}

/// The vessel motion file of [`ConvertOptions`], read once.
struct VesselFile {
    /// Absolute path (a relative one is relative to the working directory).
    path: PathBuf,
    /// The offset that puts its first row at t = 0 (0 if unreadable: validation then reports
    /// the file).
    time_offset: f64,
    /// Its length after that shift [s], if readable.
    duration: Option<f64>,
}

impl VesselFile {
    /// Reads the file given to `--vessel-motion` (a relative path is relative to the working
    /// directory, as on any command line), or the error naming it, reported once.
    fn read(given: &Path) -> Result<Self, Box<Diagnostic>> {
        let cwd = std::env::current_dir().unwrap_or_default();
        let path = if given.is_absolute() {
            given.to_path_buf()
        } else {
            cwd.join(given)
        };
        let columns = "t, x, y, z, roll, pitch, yaw";
        let rows = crate::scenario::tables::read_table::<7>(&path, columns).map_err(|e| {
            let d = Diagnostic::new(&path, "", None, "--vessel-motion", e)
                .expected("columns t [s], x, y, z [m], roll, pitch, yaw [deg]")
                .hint(if given.is_absolute() {
                    "check the path given to --vessel-motion".to_string()
                } else {
                    format!(
                        "the path given to --vessel-motion is relative to the working \
                         directory, {}",
                        cwd.display()
                    )
                });
            Box::new(d)
        })?;
        let (first, last) = (rows.first().map(|r| r[0]), rows.last().map(|r| r[0]));
        Ok(Self {
            time_offset: first.map(|t| -t).unwrap_or(0.0),
            duration: first.zip(last).map(|(a, b)| b - a),
            path,
        })
    }
}

fn convert_lines(
    c: &mut Converter,
    s: &Section,
    points: &[PointSpec],
    refused_rod_ends: &[String],
) -> (Vec<LineSpec>, bool) {
    const S: &str = "LINES";
    let mut out = Vec::new();
    let mut any_outputs = false;
    for row in &s.rows {
        if !c.check_columns(S, row, LINE_COLUMNS, LINE_COLUMNS.len() - 1) {
            continue;
        }
        let t = &row.tokens;
        let i = out.len();
        let id = &t[0].text;
        let key = |f: &str| format!("lines[{i}].{f}");
        for (field, col) in [
            ("name", "ID"),
            ("type", "LineType"),
            ("end_a", "AttachA"),
            ("end_b", "AttachB"),
            ("length", "UnstrLen"),
            ("elements", "NumSegs"),
        ] {
            c.name_key(key(field), format!("{S} › {id} › {col}"));
        }
        let attach = |c: &mut Converter, tok: &Token, col: &str| -> Spanned<String> {
            let w = tok.text.to_lowercase();
            let number = ["point", "con", "p", "c"]
                .iter()
                .find_map(|p| w.strip_prefix(p).filter(|r| r.parse::<u64>().is_ok()))
                .or_else(|| w.parse::<u64>().is_ok().then_some(w.as_str()));
            // A rod end: R#A, R#B, Rod#A, Rod#B.
            let rod_end = ["rod", "r"].iter().find_map(|p| {
                let rest = w.strip_prefix(p)?;
                let digits = rest.trim_end_matches(['a', 'b']);
                let end = &rest[digits.len()..];
                (digits.parse::<u64>().is_ok() && (end == "a" || end == "b"))
                    .then(|| format!("R{digits}{}", end.to_uppercase()))
            });
            match (number, rod_end) {
                (Some(n), _) => spanned(tok, point_name(n)),
                (None, Some(end)) => {
                    if !points.iter().any(|p| p.name.get_ref() == &end)
                        && !refused_rod_ends.contains(&end)
                    {
                        let d = c
                            .diag(
                                Some(tok.span.clone()),
                                &format!("{S} › {id} › {col}"),
                                format!(
                                    "line {id} is attached to `{}`, an end of a rod that is not \
                                     in the RODS table",
                                    tok.text
                                ),
                            )
                            .expected("R#A or R#B with a rod ID of the RODS table")
                            .hint("rod ends are R#A and R#B, # the rod's ID in RODS");
                        c.errors.push(d);
                    }
                    spanned(tok, end)
                }
                (None, None) => {
                    let d = c
                        .diag(
                            Some(tok.span.clone()),
                            &format!("{S} › {id} › {col}"),
                            format!("`{}` is not a point or a rod end", tok.text),
                        )
                        .expected(
                            "a point ID from the POINTS table (3, P3, Point3, C3 or Con3) or a \
                             rod end (R1A, R1B)",
                        )
                        .hint("lines attach to points by their ID and to rods by R#A or R#B");
                    c.errors.push(d);
                    spanned(tok, tok.text.clone())
                }
            }
        };
        let end_a = attach(c, &t[2], "AttachA");
        let end_b = attach(c, &t[3], "AttachB");
        for (end, tok, col) in [(&end_a, &t[2], "AttachA"), (&end_b, &t[3], "AttachB")] {
            let known = points.iter().any(|p| p.name.get_ref() == end.get_ref());
            if !known && end.get_ref().starts_with('P') {
                let ids: Vec<&str> = points.iter().map(|p| &p.name.get_ref()[1..]).collect();
                let d = c
                    .diag(
                        Some(tok.span.clone()),
                        &format!("{S} › {id} › {col}"),
                        format!(
                            "line {id} is attached to point {}, which is not in the POINTS table",
                            &end.get_ref()[1..]
                        ),
                    )
                    .expected(format!("a point ID: {}", ids.join(", ")))
                    .hint("add the point to the POINTS table, or correct the ID");
                c.errors.push(d);
            }
        }
        let mut length = c.number(&t[4], &format!("{S} › {id}"), "UnstrLen", "m");
        if let Some(l) = length
            && l < 0.0
        {
            // MoorDyn: a negative length is a multiple of the distance between the ends.
            // Points on bodies are placed by their body: their positions are in its axes.
            let at = |name: &str| {
                points
                    .iter()
                    .find(|p| p.name.get_ref() == name)
                    .filter(|p| *p.kind.get_ref() != PointKindSpec::Body)
                    .and_then(|p| p.position.as_ref().map(|x| *x.get_ref()))
            };
            if let (Some(a), Some(b)) = (at(end_a.get_ref()), at(end_b.get_ref())) {
                let span =
                    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt();
                length = Some(-l * span);
                c.note(
                    row.line,
                    format!(
                        "line {id}: UnstrLen {} is {} × the {span:.6} m between its ends: {} m",
                        t[4].text,
                        -l,
                        -l * span
                    ),
                );
            } else {
                let d = c
                    .diag(
                        Some(t[4].span.clone()),
                        &format!("{S} › {id} › UnstrLen"),
                        format!(
                            "line {id}: UnstrLen {} < 0 is a multiple of the distance between \
                             its ends, and an end on a body has no place before the body is \
                             placed",
                            t[4].text
                        ),
                    )
                    .expected("the unstretched length in m, > 0")
                    .hint("give the length in metres");
                c.errors.push(d);
                length = Some(1.0);
            }
        }
        let segments = c.count(&t[5], &format!("{S} › {id}"), "NumSegs");
        if let Some(flags) = t.get(6)
            && flags.text != "-"
            && !flags.text.is_empty()
        {
            any_outputs = true;
            c.note(
                row.line,
                format!(
                    "line {id}: output flags `{}` are written as shape snapshots \
                     (snapshots/{}.csv: positions and tension of every node), not as MoorDyn's \
                     per-line files",
                    flags.text,
                    line_name(id)
                ),
            );
        }
        out.push(LineSpec {
            name: spanned(&t[0], line_name(id)),
            end_a,
            end_b,
            formulation: None,
            mass_matrix: Some(MassMatrixSpec::Lumped),
            strain: None,
            modal_filter: None,
            shock_filter: None,
            clamp_a: None,
            clamp_b: None,
            line_type: Some(spanned(&t[1], t[1].text.clone())),
            length: Some(spanned(&t[4], length.unwrap_or(1.0))),
            elements: Some(spanned(&t[5], segments.unwrap_or(1))),
            order: None,
            sections: Vec::new(),
            winch: None,
            failure: None,
        });
    }
    (out, any_outputs)
}
