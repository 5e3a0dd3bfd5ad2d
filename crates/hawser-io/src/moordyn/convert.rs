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
use crate::scenario::diagnostics::{closest, line_number};
use crate::scenario::schema::*;
use crate::scenario::{Diagnostic, ScenarioError};
use std::ops::Range;
use std::path::{Path, PathBuf};
use toml::Spanned;

mod water;

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
        for d in &mut e.diagnostics {
            // the longest matching prefix names the most specific column
            let best = self
                .key_names
                .iter()
                .filter(|(k, _)| {
                    d.key == *k
                        || d.key.starts_with(&format!("{k}."))
                        || d.key.starts_with(&format!("{k}["))
                })
                .max_by_key(|(k, _)| k.len());
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
    errors: Vec<Diagnostic>,
    notes: Vec<Note>,
    key_names: Vec<(String, String)>,
}

fn spanned<T>(t: &Token, v: T) -> Spanned<T> {
    Spanned::new(t.span.clone(), v)
}

/// Parses a number as MoorDyn does (C `atof`), accepting Fortran `D` exponents too.
fn parse_number(text: &str) -> Option<f64> {
    let t = text.replace(['d', 'D'], "e");
    t.parse::<f64>().ok().filter(|x| x.is_finite())
}

impl<'a> Converter<'a> {
    fn diag(
        &self,
        span: Option<Range<usize>>,
        key: &str,
        message: impl Into<String>,
    ) -> Diagnostic {
        Diagnostic::new(self.file, self.source, span, key, message)
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
        line_number(self.source, span.start)
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
                "hawser cannot run this deck with its {} row{} yet; remove the section to run the \
                 rest, or model it in a hawser scenario",
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
        match s.kind {
            SectionKind::RodTypes => c.refuse_section(s, "rods need rigid-body support (planned)"),
            SectionKind::Rods => c.refuse_section(s, "rods need rigid-body support (planned)"),
            SectionKind::Bodies => c.refuse_section(s, "rigid bodies are not available yet"),
            SectionKind::Unsupported => c.refuse_section(s, "hawser does not read this section"),
            _ => {}
        }
    }
    let line_types = match deck.section(SectionKind::LineTypes) {
        Some(s) => convert_line_types(&mut c, s, dir),
        None => Vec::new(),
    };
    let vessel = options.vessel_motion.as_deref().map(VesselFile::read);
    let option_rows = deck
        .section(SectionKind::Options)
        .map(|s| s.rows.as_slice())
        .unwrap_or(&[]);
    let opts = read_options(&mut c, option_rows);
    let (points, coupled) = match deck.section(SectionKind::Points) {
        Some(s) => convert_points(&mut c, s, vessel.as_ref()),
        None => (Vec::new(), 0),
    };
    let (lines, line_outputs) = match deck.section(SectionKind::Lines) {
        Some(s) => convert_lines(&mut c, s, &points),
        None => (Vec::new(), false),
    };
    if deck.section(SectionKind::Lines).is_none() {
        let d = c
            .diag(Some(0..0), "LINES", "the deck has no LINES section")
            .expected("a `---- LINES ----` section with rows ID LineType AttachA AttachB UnstrLen NumSegs LineOutputs")
            .hint("hawser runs decks with at least one line");
        c.errors.push(d);
    }
    let channels = match deck.section(SectionKind::Outputs) {
        Some(s) if !lines.is_empty() => convert_outputs(&mut c, s, &lines),
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
            bodies: Vec::new(),
            obstacles: Vec::new(),
        },
        notes: c.notes,
        key_names: c.key_names,
    })
}

fn convert_line_types(c: &mut Converter, s: &Section, dir: &Path) -> Vec<LineTypeSpec> {
    const S: &str = "LINE TYPES";
    let mut out = Vec::new();
    for row in &s.rows {
        if !c.check_columns(S, row, LINE_TYPE_COLUMNS, 10) {
            continue;
        }
        let t = &row.tokens;
        if t.len() == 12 {
            let d = c
                .diag(
                    Some(t[11].span.clone()),
                    &format!("{S} › {} › dF", t[0].text),
                    "`dF` without `cF`",
                )
                .expected("10 columns, 11 with the VIV lift coefficient Cl, or 13 with Cl dF cF")
                .hint("give both dF and cF, or neither");
            c.errors.push(d);
            continue;
        }
        if let Some(cl) = t.get(10) {
            match c.number(cl, &format!("{S} › {}", t[0].text), "Cl", "-") {
                Some(x) if x != 0.0 => {
                    let d = c
                        .diag(Some(cl.span.clone()), &format!("{S} › {} › Cl", t[0].text), "vortex-induced vibration (Cl > 0) is not supported")
                        .expected("Cl = 0")
                        .hint("hawser has no VIV model; set Cl to 0 (or drop the VIV columns) to run without it");
                    c.errors.push(d);
                }
                Some(_) => c.note(
                    row.line,
                    format!(
                        "line type `{}`: VIV columns with Cl = 0 have no effect",
                        t[0].text
                    ),
                ),
                None => {}
            }
        }
        let i = out.len();
        let name = t[0].text.clone();
        let key = |f: &str| format!("line_types[{i}].{f}");
        for (field, col) in [
            ("name", "TypeName"),
            ("diameter", "Diam"),
            ("mass_per_length", "Mass/m"),
            ("axial_stiffness", "EA"),
            ("tension_strain", "EA"),
            ("axial_damping", "BA/-zeta"),
            ("axial_damping_ratio", "BA/-zeta"),
            ("bending_stiffness", "EI"),
            ("normal_drag", "Cd"),
            ("normal_added_mass", "Ca"),
            ("tangential_drag", "CdAx"),
            ("tangential_added_mass", "CaAx"),
        ] {
            c.name_key(key(field), format!("{S} › {name} › {col}"));
        }
        let diameter = c.number(&t[1], &format!("{S} › {}", t[0].text), "Diam", "m");
        let mass = c.number(&t[2], &format!("{S} › {}", t[0].text), "Mass/m", "kg/m");
        let (axial_stiffness, tension_strain) = match parse_number(&t[3].text) {
            Some(ea) => (Some(spanned(&t[3], ea)), None),
            None if t[3].text.contains('|') => {
                let d = c
                    .diag(
                        Some(t[3].span.clone()),
                        &format!("{S} › {name} › EA"),
                        "visco-elastic `EA|EAd` stiffness is not supported",
                    )
                    .expected("EA as a number in N, or the name of a tension–strain table file")
                    .hint(
                        "give the static stiffness EA; hawser's axial damping is in the BA column",
                    );
                c.errors.push(d);
                (None, None)
            }
            None => match read_tension_strain(&dir.join(&t[3].text)) {
                Ok(rows) => {
                    let line = row.line;
                    c.note(
                        line,
                        format!(
                            "line type `{name}`: tension–strain table read from {} ({} points)",
                            t[3].text,
                            rows.len()
                        ),
                    );
                    (None, Some(spanned(&t[3], rows)))
                }
                Err(msg) => {
                    let d = c
                        .diag(
                            Some(t[3].span.clone()),
                            &format!("{S} › {name} › EA"),
                            format!("`EA` is neither a number nor a readable table file: {msg}"),
                        )
                        .expected(
                            "EA in N, or a file of rows `strain tension` relative to the deck",
                        )
                        .hint("the file path is relative to the deck's folder");
                    c.errors.push(d);
                    (None, None)
                }
            },
        };
        let ba = if parse_number(&t[4].text).is_none()
            && (t[4].text.contains('|')
                || !t[4]
                    .text
                    .starts_with(|ch: char| ch == '-' || ch == '.' || ch.is_ascii_digit()))
        {
            let d = c
                .diag(Some(t[4].span.clone()), &format!("{S} › {name} › BA/-zeta"), "nonlinear or dynamic-spring axial damping (`BA` table file or `BA|BAd`) is not supported")
                .expected("a damping coefficient in N·s, or −ζ (a fraction of critical damping)")
                .hint("give a constant BA");
            c.errors.push(d);
            None
        } else {
            c.number(
                &t[4],
                &format!("{S} › {}", t[0].text),
                "BA/-zeta",
                "N·s (or −ζ, a fraction of critical)",
            )
        };
        if parse_number(&t[5].text).is_none()
            && !t[5]
                .text
                .starts_with(|ch: char| ch == '-' || ch == '.' || ch.is_ascii_digit())
        {
            let d = c
                .diag(
                    Some(t[5].span.clone()),
                    &format!("{S} › {name} › EI"),
                    "a bending moment–curvature table is not supported",
                )
                .expected("EI in N·m²")
                .hint("give a constant EI");
            c.errors.push(d);
        }
        let (axial_damping, axial_damping_ratio) = match ba {
            Some(x) if x < 0.0 => (None, Some(spanned(&t[4], -x))),
            Some(x) => (Some(spanned(&t[4], x)), None),
            None => (None, None),
        };
        let ei = parse_number(&t[5].text);
        if ei.is_some_and(|x| x > 0.0) {
            c.note(
                row.line,
                format!(
                    "line type `{name}`: EI = {} N·m² is kept as `bending_stiffness`; MoorDyn \
                     applies it as nodal bending moments, hawser's `fe` lines carry no bending, \
                     so this line is modelled without it",
                    t[5].text
                ),
            );
        }
        let cd = c.number(&t[6], &format!("{S} › {}", t[0].text), "Cd", "-");
        let ca = c.number(&t[7], &format!("{S} › {}", t[0].text), "Ca", "-");
        let cdax = c.number(&t[8], &format!("{S} › {}", t[0].text), "CdAx", "-");
        let caax = c.number(&t[9], &format!("{S} › {}", t[0].text), "CaAx", "-");
        if let Some(x) = cdax
            && x != 0.0
        {
            c.note(
                row.line,
                format!(
                    "line type `{name}`: CdAx {} on π·d becomes tangential_drag {} on d (× π)",
                    t[8].text,
                    x * std::f64::consts::PI
                ),
            );
        }
        let f = |v: Option<f64>, tok: &Token| v.map(|x| spanned(tok, x));
        out.push(LineTypeSpec {
            name: spanned(&t[0], name.clone()),
            diameter: spanned(&t[1], diameter.unwrap_or(1.0)),
            mass_per_length: spanned(&t[2], mass.unwrap_or(1.0)),
            axial_stiffness,
            tension_strain,
            axial_damping,
            axial_damping_ratio,
            normal_drag: f(cd, &t[6]),
            tangential_drag: f(cdax.map(|x| x * std::f64::consts::PI), &t[8]),
            loading_functions: None,
            normal_added_mass: f(ca, &t[7]),
            tangential_added_mass: f(caax, &t[9]),
            compression: None,
            bending_stiffness: f(ei.filter(|&x| x != 0.0), &t[5]),
            bending_damping: None,
        });
    }
    out
}

/// Reads a MoorDyn tension–strain table: rows `strain tension` [-, N], whitespace or comma
/// separated, header lines skipped; a `(0, 0)` row is added when missing.
fn read_tension_strain(path: &Path) -> Result<Vec<[f64; 2]>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut rows = Vec::new();
    for line in text.lines() {
        let nums: Vec<f64> = line
            .split([',', ' ', '\t', ';'])
            .filter(|s| !s.is_empty())
            .map_while(parse_number)
            .collect();
        if nums.len() >= 2 {
            rows.push([nums[0], nums[1]]);
        }
    }
    if rows.is_empty() {
        return Err(format!("{}: no rows `strain tension`", path.display()));
    }
    if rows[0] != [0.0, 0.0] {
        rows.insert(0, [0.0, 0.0]);
    }
    Ok(rows)
}

/// A point's name in the scenario: `P` and its MoorDyn ID.
fn point_name(id: &str) -> String {
    format!("P{id}")
}

/// A line's name in the scenario: `L` and its MoorDyn ID.
fn line_name(id: &str) -> String {
    format!("L{id}")
}

fn convert_points(
    c: &mut Converter,
    s: &Section,
    vessel: Option<&VesselFile>,
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
        let base = kind_word.trim_end_matches(|ch: char| ch.is_ascii_digit());
        let kind = match base {
            "fixed" | "fix" | "anchor" => Some(PointKindSpec::Fixed),
            "free" | "connect" | "con" | "point" => Some(PointKindSpec::Free),
            "coupled" | "vessel" | "ves" | "cpld" | "fairlead" => Some(PointKindSpec::Prescribed),
            "body" | "turbine" => {
                let d = c
                    .diag(
                        Some(t[1].span.clone()),
                        &format!("{S} › {} › Type", t[0].text),
                        format!("point {} is attached to a body (`{}`)", t[0].text, t[1].text),
                    )
                    .hint("rigid bodies are not available yet; make the point `Coupled` to drive it with a vessel motion, or `Fixed`");
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
            MotionSpec {
                kind: spanned(
                    &word,
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
                file: vessel.map(|v| spanned(&word, v.path.display().to_string())),
                time_offset: vessel.map(|v| spanned(&word, v.time_offset)),
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
    fn read(path: &Path) -> Self {
        let path = if path.is_absolute() {
            path.to_path_buf()
        } else {
            std::env::current_dir().unwrap_or_default().join(path)
        };
        let rows = crate::scenario::build::read_table::<7>(&path, "").unwrap_or_default();
        let (first, last) = (rows.first().map(|r| r[0]), rows.last().map(|r| r[0]));
        Self {
            time_offset: first.map(|t| -t).unwrap_or(0.0),
            duration: first.zip(last).map(|(a, b)| b - a),
            path,
        }
    }
}

fn convert_lines(c: &mut Converter, s: &Section, points: &[PointSpec]) -> (Vec<LineSpec>, bool) {
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
            match number {
                Some(n) => spanned(tok, point_name(n)),
                None => {
                    let rod = w.starts_with('r');
                    let d = c
                        .diag(
                            Some(tok.span.clone()),
                            &format!("{S} › {id} › {col}"),
                            if rod {
                                format!("line {id} is attached to a rod end (`{}`); rods are not available yet", tok.text)
                            } else {
                                format!("`{}` is not a point", tok.text)
                            },
                        )
                        .expected("a point ID from the POINTS table: 3, P3, Point3, C3 or Con3")
                        .hint(if rod {
                            "attach the line to a Coupled or Fixed point instead of the rod"
                        } else {
                            "lines attach to points by their ID"
                        });
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
            let at = |name: &str| {
                points
                    .iter()
                    .find(|p| p.name.get_ref() == name)
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
        });
    }
    (out, any_outputs)
}

/// The OPTIONS rows by lower-case name: (value token, row).
struct Options<'r> {
    rows: Vec<(String, &'r Token, &'r Row)>,
}

impl<'r> Options<'r> {
    fn get(&self, names: &[&str]) -> Option<(&'r Token, &'r Row)> {
        self.rows
            .iter()
            .rev()
            .find(|(n, _, _)| names.contains(&n.as_str()))
            .map(|(_, t, r)| (*t, *r))
    }
}

/// Options hawser reads, with their MoorDyn-C 2.7 spellings (lower case).
const USED_OPTIONS: &[&str] = &[
    "dtm",
    "dt",
    "cfl",
    "tscheme",
    "g",
    "gravity",
    "rho",
    "wtrdnsty",
    "wtrdpth",
    "depth",
    "kbot",
    "kb",
    "cbot",
    "cb",
    "frictioncoefficient",
    "fricdamp",
    "statdynfricscale",
    "dtout",
    "wavekin",
    "dtwave",
    "currents",
    "seafloorfile",
];

/// Options read but without effect in hawser, and the note that follows the option's name.
const NOTED_OPTIONS: &[(&[&str], &str)] = &[
    (
        &[
            "dtic",
            "icdt",
            "tmaxic",
            "ictmax",
            "cdscaleic",
            "icdfac",
            "threshic",
            "icthresh",
            "icgendynamic",
            "gendynamicic",
        ],
        " (initial-condition control) is not used: hawser starts from its Newton static \
         equilibrium, the state MoorDyn's initial-condition solver approximates",
    ),
    (
        &["fileic", "icfile", "inputic"],
        " (initial-condition file) is not used: hawser starts from its Newton static \
         equilibrium, the state MoorDyn's initial-condition solver approximates",
    ),
    (
        &["writelog"],
        " has no effect: hawser reports on the terminal",
    ),
    (
        &["writeunits"],
        " has no effect: hawser's column headers always carry units",
    ),
    (
        &["disableoutput", "disableouttime"],
        " has no effect: hawser always writes its results and reports progress",
    ),
    (
        &["echo"],
        " has no effect: hawser prints conversion notes instead",
    ),
    (
        &["wavekin_rampt"],
        " has no effect: MoorDyn 2.7 does not read it (hawser ramps its waves up by its own \
         `ramp_time`)",
    ),
    (
        &["unifycurrentgrid"],
        " has no effect: the current profile is used as given",
    ),
];

/// Every option name hawser knows.
fn known_options() -> impl Iterator<Item = &'static str> {
    USED_OPTIONS.iter().copied().chain(
        NOTED_OPTIONS
            .iter()
            .flat_map(|(names, _)| names.iter().copied()),
    )
}

fn read_options<'r>(c: &mut Converter, rows: &'r [Row]) -> Options<'r> {
    let mut out = Options { rows: Vec::new() };
    for row in rows {
        let Some(value) = row.tokens.first() else {
            continue;
        };
        let Some(name) = row.tokens.get(1) else {
            let d = c
                .diag(
                    Some(value.span.clone()),
                    "OPTIONS",
                    "an option row needs a value and a name",
                )
                .expected("`value name [description]`, e.g. `0.002 dtM`");
            c.errors.push(d);
            continue;
        };
        let lower = name.text.to_lowercase();
        if !known_options().any(|k| k == lower) {
            let hint = match closest(&lower, known_options()) {
                Some(k) => format!("did you mean `{k}`? (option names are case-insensitive here)"),
                None => "MoorDyn would ignore it too; remove it, or check the spelling".to_string(),
            };
            c.note(
                row.line,
                format!("unknown option `{}` is ignored ({hint})", name.text),
            );
            continue;
        }
        out.rows.push((lower, value, row));
    }
    out
}

fn environment_of(
    c: &mut Converter,
    o: &Options,
    dir: &Path,
    points: &[PointSpec],
) -> EnvironmentSpec {
    let num = |c: &mut Converter, names: &[&str], unit: &str| -> Option<Spanned<f64>> {
        let (t, row) = o.get(names)?;
        let name = row.tokens[1].text.clone();
        c.number(t, "OPTIONS", &name, unit).map(|x| spanned(t, x))
    };
    let gravity = num(c, &["g", "gravity"], "m/s²");
    let water_density = num(c, &["rho", "wtrdnsty"], "kg/m³");
    let mut depth = num(c, &["wtrdpth", "depth"], "m");
    // MoorDyn: the depth is at least that of the deepest point (0 when not given).
    let deepest = points
        .iter()
        .filter_map(|p| p.position.as_ref())
        .map(|x| (-x.get_ref()[2], x.span()))
        .fold(None, |m: Option<(f64, Range<usize>)>, (d, s)| match m {
            Some((md, _)) if md >= d => m,
            _ => Some((d, s)),
        });
    if let Some((d, span)) = deepest
        && d > 0.0
        && depth.as_ref().is_none_or(|x| *x.get_ref() < d)
    {
        let line = c.line_of(&span);
        c.note(
            line,
            match &depth {
                Some(x) => format!(
                    "WtrDpth {} is above the deepest point: the seabed is lowered to z = −{d} m, as MoorDyn does",
                    x.get_ref()
                ),
                None => format!(
                    "no WtrDpth: the seabed is at the deepest point, z = −{d} m, as in MoorDyn"
                ),
            },
        );
        depth = Some(Spanned::new(span, d));
    }
    let kbot = num(c, &["kbot", "kb"], "Pa/m");
    let cbot = num(c, &["cbot", "cb"], "Pa·s/m");
    let mu = num(c, &["frictioncoefficient"], "-");
    for (k, v) in [
        ("environment.gravity", "g"),
        ("environment.water_density", "WtrDnsty"),
        ("environment.depth", "WtrDpth"),
        ("environment.seabed.stiffness", "kBot"),
        ("environment.seabed.damping", "cBot"),
        (
            "environment.seabed.friction_coefficient",
            "FrictionCoefficient",
        ),
    ] {
        c.name_key(k.to_string(), format!("OPTIONS › {v}"));
    }
    let friction_damping = num(c, &["fricdamp"], "N·s/m");
    let static_friction_scale = num(c, &["statdynfricscale"], "-");
    c.name_key(
        "environment.seabed.friction_damping".into(),
        "OPTIONS › FricDamp".into(),
    );
    c.name_key(
        "environment.seabed.static_friction_scale".into(),
        "OPTIONS › StatDynFricScale".into(),
    );
    // MoorDyn's friction law is always its own: FricDamp defaults to 200 N·s/m.
    let friction = mu.as_ref().filter(|m| *m.get_ref() > 0.0).map(|m| {
        let anchor = Token {
            text: String::new(),
            span: m.span(),
        };
        (
            friction_damping.unwrap_or_else(|| spanned(&anchor, 200.0)),
            static_friction_scale,
        )
    });
    let waves = water::waves_of(c, o, dir);
    if let Some((t, _)) = o.get(&["seafloorfile"]) {
        let d = c
            .diag(
                Some(t.span.clone()),
                "OPTIONS › SeafloorFile",
                "bathymetry files are not supported",
            )
            .expected("a flat seabed at WtrDpth")
            .hint("remove SeafloorFile to run on a flat bed at WtrDpth");
        c.errors.push(d);
    }
    let current = match o.get(&["currents"]) {
        Some((t, row)) => {
            match parse_number(&t.text) {
                Some(0.0) => None,
                Some(1.0) => current_profile(c, t, row, dir),
                Some(2.0) => water::dynamic_current(c, t, row, dir),
                _ => {
                    let d = c
                    .diag(
                        Some(t.span.clone()),
                        "OPTIONS › Currents",
                        format!("Currents mode `{}` is not supported", t.text),
                    )
                    .expected(
                        "0 (none), 1 (steady profile from current_profile.txt) or 2 (profiles \
                         against time from current_profile_dynamic.txt)",
                    )
                    .hint("MoorDyn's node-approach and 4D gridded currents are not read: use 1 or 2");
                    c.errors.push(d);
                    None
                }
            }
        }
        None => None,
    };
    let seabed = depth.as_ref().map(|_| SeabedSpec {
        stiffness: kbot,
        damping_ratio: None,
        damping: cbot,
        friction_coefficient: mu,
        friction_velocity: None,
        friction_damping: friction.as_ref().map(|f| f.0.clone()),
        static_friction_scale: friction.and_then(|f| f.1),
    });
    EnvironmentSpec {
        gravity,
        water_density,
        air_density: None,
        depth,
        seabed,
        current,
        waves,
    }
}

/// `Currents 1`: a steady profile from `current_profile.txt` beside the deck (MoorDyn reads
/// it from the deck's folder): rows `z ux uy uz` after three header lines.
fn current_profile(c: &mut Converter, t: &Token, row: &Row, dir: &Path) -> Option<CurrentSpec> {
    let path = dir.join("current_profile.txt");
    let text = match std::fs::read_to_string(&path) {
        Ok(s) => s,
        Err(e) => {
            let d = c
                .diag(
                    Some(t.span.clone()),
                    "OPTIONS › Currents",
                    format!("Currents 1 needs {}: {e}", path.display()),
                )
                .expected("current_profile.txt beside the deck: rows `z ux uy uz` [m, m/s]")
                .hint("put the profile file next to the deck, or set Currents to 0");
            c.errors.push(d);
            return None;
        }
    };
    let mut rows: Vec<[f64; 4]> = Vec::new();
    for line in text.lines() {
        let nums: Vec<f64> = line
            .split([',', ' ', '\t'])
            .filter(|s| !s.is_empty())
            .map_while(parse_number)
            .collect();
        if nums.len() >= 2 && line.split_whitespace().count() == nums.len() {
            rows.push([
                nums[0],
                nums[1],
                nums.get(2).copied().unwrap_or(0.0),
                nums.get(3).copied().unwrap_or(0.0),
            ]);
        }
    }
    rows.sort_by(|a, b| a[0].total_cmp(&b[0]));
    c.note(
        row.line,
        format!(
            "Currents 1: {} depths read from {}",
            rows.len(),
            path.display()
        ),
    );
    Some(CurrentSpec {
        kind: spanned(t, CurrentKind::Profile),
        velocity: None,
        profile: Some(spanned(t, rows)),
        z: None,
        times: None,
        ux: None,
        uy: None,
        uz: None,
    })
}

fn simulation_of(
    c: &mut Converter,
    o: &Options,
    duration: Option<f64>,
    vessel_end: Option<f64>,
    channels: Vec<Spanned<String>>,
    line_outputs: bool,
    coupled: usize,
) -> SimulationSpec {
    let mut time_step = None;
    if let Some((t, row)) = o.get(&["dtm", "dt"])
        && let Some(x) = c.number(t, "OPTIONS", &row.tokens[1].text, "s")
    {
        time_step = Some(spanned(t, TimeStepSpec::Value(x)));
        c.name_key("simulation.time_step".into(), "OPTIONS › dtM".into());
    }
    if let Some((t, row)) = o.get(&["cfl"]) {
        c.note(
            row.line,
            format!(
                "CFL {}: hawser takes its time step from its own stability bound{}",
                t.text,
                if time_step.is_some() {
                    " only where dtM exceeds it"
                } else {
                    " (time_step = \"auto\")"
                }
            ),
        );
    }
    if let Some((t, row)) = o.get(&["tscheme"]) {
        if t.text.eq_ignore_ascii_case("rk4") {
        } else {
            c.note(
                row.line,
                format!(
                    "tScheme {}: hawser integrates with RK4 (fourth order; it needs no smaller \
                     step than MoorDyn's schemes)",
                    t.text
                ),
            );
        }
    }
    let mut output_interval = None;
    if let Some((t, row)) = o.get(&["dtout"])
        && let Some(x) = c.number(t, "OPTIONS", &row.tokens[1].text, "s")
    {
        if x > 0.0 {
            output_interval = Some(spanned(t, x));
            c.name_key(
                "simulation.output_interval".into(),
                "OPTIONS › dtOut".into(),
            );
        } else if let Some(TimeStepSpec::Value(dt)) = time_step.as_ref().map(|s| s.get_ref()) {
            output_interval = Some(spanned(t, *dt));
            c.note(row.line, "dtOut 0: a sample every time step");
        }
    }
    for (names, note) in NOTED_OPTIONS {
        for (_, _, row) in o
            .rows
            .iter()
            .filter(|(n, _, _)| names.contains(&n.as_str()))
        {
            c.note(row.line, format!("{}{note}", row.tokens[1].text));
        }
    }
    let duration = match (duration, vessel_end) {
        (Some(d), _) => d,
        (None, Some(d)) if coupled > 0 => d,
        _ => {
            c.note(
                0,
                "a MoorDyn deck has no duration: running 60 s (give --duration to change it)",
            );
            60.0
        }
    };
    let anchor = Token {
        text: String::new(),
        span: 0..0,
    };
    SimulationSpec {
        duration: spanned(&anchor, duration),
        time_step,
        safety_factor: None,
        scheme: Some(SchemeSpec::Rk4),
        output_interval: output_interval.clone(),
        snapshot_interval: if line_outputs {
            Some(output_interval.unwrap_or_else(|| spanned(&anchor, 0.1)))
        } else {
            None
        },
        initial_condition: Some(spanned(&anchor, InitialConditionSpec::Statics)),
        release: Vec::new(),
        channels,
    }
}

/// OUTPUTS: MoorDyn channel names become labelled hawser channels.
fn convert_outputs(c: &mut Converter, s: &Section, lines: &[LineSpec]) -> Vec<Spanned<String>> {
    let segments = |line: &str| {
        lines
            .iter()
            .find(|l| l.name.get_ref() == line)
            .and_then(|l| l.elements.as_ref().map(|n| *n.get_ref() as usize))
    };
    let mut out = Vec::new();
    for row in &s.rows {
        for t in &row.tokens {
            match output_channel(&t.text, segments) {
                Ok(spec) => out.push(spanned(t, format!("{} = {spec}", t.text))),
                Err(msg) => {
                    let d = c
                        .diag(Some(t.span.clone()), "OUTPUTS", msg)
                        .expected(
                            "FairTen#, AnchTen#, L#N#PX|PY|PZ|VX|VY|VZ|T, P#PX|PY|PZ|VX|VY|VZ",
                        )
                        .hint("# is the line, node or point number, e.g. FairTen1, L1N20T, P4PZ");
                    c.errors.push(d);
                }
            }
        }
    }
    out
}

/// The hawser channel of a MoorDyn output name (case-insensitive, as in MoorDyn-C 2.7's
/// `decomposeString`); `segments` gives a line's segment count by its scenario name.
/// The tension `T` of an end node is MoorDyn's |Fnet| of that node (`node_force`).
pub fn output_channel(
    name: &str,
    segments: impl Fn(&str) -> Option<usize>,
) -> Result<String, String> {
    let u = name.to_uppercase();
    let split_num = |s: &str| -> Option<(String, String)> {
        let digits: String = s.chars().take_while(|ch| ch.is_ascii_digit()).collect();
        (!digits.is_empty()).then(|| (digits.clone(), s[digits.len()..].to_string()))
    };
    for (prefix, end) in [("FAIRTEN", "end_b"), ("ANCHTEN", "end_a")] {
        if let Some(rest) = u.strip_prefix(prefix) {
            return match split_num(rest) {
                Some((n, tail)) if tail.is_empty() => {
                    let line = line_name(&n);
                    if segments(&line).is_none() {
                        return Err(format!("`{name}`: there is no line {n}"));
                    }
                    Ok(format!("{line}.{end}.node_force"))
                }
                _ => Err(format!("`{name}` is not {prefix}<line number>")),
            };
        }
    }
    let quantity = |q: &str| -> Option<&'static str> {
        Some(match q {
            "PX" => "x",
            "PY" => "y",
            "PZ" => "z",
            "VX" => "vx",
            "VY" => "vy",
            "VZ" => "vz",
            "T" | "TEN" => "tension",
            "FX" => "fx",
            "FY" => "fy",
            "FZ" => "fz",
            _ => return None,
        })
    };
    let line_rest = u
        .strip_prefix("LINE")
        .or_else(|| u.strip_prefix('L'))
        .and_then(split_num);
    if let Some((l, tail)) = line_rest {
        let line = line_name(&l);
        let Some(n) = segments(&line) else {
            return Err(format!("`{name}`: there is no line {l}"));
        };
        let form =
            || format!("`{name}`: a line channel is L<line>N<node><quantity>, e.g. L{l}N{n}T");
        let tail = tail
            .strip_prefix("NODE")
            .or_else(|| tail.strip_prefix('N'))
            .ok_or_else(form)?;
        let (node, q) = if let Some(q) = tail.strip_prefix('A') {
            (0, q.to_string())
        } else if let Some(q) = tail.strip_prefix('B') {
            (n, q.to_string())
        } else {
            let (k, q) = split_num(tail).ok_or_else(form)?;
            (k.parse::<usize>().map_err(|_| form())?, q)
        };
        if node > n {
            return Err(format!("`{name}`: line {l} has nodes 0 … {n}"));
        }
        let end = if node == 0 {
            Some("end_a")
        } else if node == n {
            Some("end_b")
        } else {
            None
        };
        return match (quantity(&q), end) {
            (Some("tension"), Some(e)) => Ok(format!("{line}.{e}.node_force")),
            (Some(f @ ("fx" | "fy" | "fz")), Some(e)) => Ok(format!("{line}.{e}.{f}")),
            (Some("fx" | "fy" | "fz"), None) => Err(format!(
                "`{name}`: node forces are available at the line ends (N0 and N{n}) only"
            )),
            (Some(q), _) => Ok(format!("{line}.node{node}.{q}")),
            (None, _) => Err(format!(
                "`{name}`: line node quantity `{q}` is not available (PX, PY, PZ, VX, VY, VZ, T)"
            )),
        };
    }
    let point_rest = u
        .strip_prefix("POINT")
        .or_else(|| u.strip_prefix('P'))
        .and_then(split_num);
    if let Some((p, q)) = point_rest {
        return match quantity(&q).filter(|q| *q != "tension") {
            Some(q) => Ok(format!("{}.{q}", point_name(&p))),
            None => Err(format!(
                "`{name}`: point quantity `{q}` is not available (PX, PY, PZ, VX, VY, VZ, FX, FY, FZ)"
            )),
        };
    }
    if u.starts_with("CON") || u.starts_with('C') {
        return Err(format!(
            "`{name}`: MoorDyn v2 names point channels P<point><quantity> (Con/C are v1 names)"
        ));
    }
    if u.starts_with('R') || u.starts_with('B') {
        return Err(format!("`{name}`: rods and bodies are not available yet"));
    }
    Err(format!("unknown MoorDyn output channel `{name}`"))
}
