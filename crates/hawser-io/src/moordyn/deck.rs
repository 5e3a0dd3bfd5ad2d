//! Lexing a MoorDyn v2 input deck into sections of rows of tokens, each token carrying its
//! byte span in the file so every later error can point at it.
//!
//! The layout MoorDyn-C 2.7 reads (`MoorDyn2.cpp`, `ReadInFile`): free text until the first
//! section header; a header is a line containing `---` and a section keyword; table sections
//! (line types, points, lines, rods, bodies) start with a row of column names and a row of
//! units in parentheses; OPTIONS rows are `value name [description]`; OUTPUTS rows are channel
//! names; the deck ends with a dashed line such as `--- need this line ---` or `--- END ---`.
//!
//! This reader is more forgiving than MoorDyn's: blank lines and tabs anywhere inside tables
//! are accepted, and the column-name and unit rows are recognised by content rather than
//! skipped blindly, so a deck without its unit row still reads correctly.

use super::super::scenario::Diagnostic;
use std::ops::Range;
use std::path::Path;

/// A whitespace-separated word of the deck and where it is.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    /// The text.
    pub text: String,
    /// Byte span in the deck.
    pub span: Range<usize>,
}

/// A data row of a section.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// 1-based line number in the deck.
    pub line: usize,
    /// Byte span of the whole line (without its newline).
    pub span: Range<usize>,
    /// The words of the row.
    pub tokens: Vec<Token>,
}

/// The sections of a MoorDyn v2 deck.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SectionKind {
    /// `LINE TYPES` / `LINE DICTIONARY`.
    LineTypes,
    /// `ROD TYPES` / `ROD DICTIONARY`.
    RodTypes,
    /// `BODIES` / `BODY LIST` / `BODY PROPERTIES`.
    Bodies,
    /// `RODS` / `ROD LIST` / `ROD PROPERTIES`.
    Rods,
    /// `POINTS` / `POINT LIST` / `POINT PROPERTIES` / `CONNECTION PROPERTIES` / `NODE PROPERTIES`.
    Points,
    /// `LINES` / `LINE LIST` / `LINE PROPERTIES`.
    Lines,
    /// `OPTIONS`.
    Options,
    /// `OUTPUTS` / `OUTPUT LIST`.
    Outputs,
    /// `FAILURE` (MoorDyn-F): line ends that release from a point or rod end.
    Failure,
    /// A section hawser does not read (`CONTROL`, `EXTERNAL LOADS`, ...).
    Unsupported,
}

impl SectionKind {
    /// Whether the section is a table with column-name and unit rows.
    fn is_table(self) -> bool {
        matches!(
            self,
            SectionKind::LineTypes
                | SectionKind::RodTypes
                | SectionKind::Bodies
                | SectionKind::Rods
                | SectionKind::Points
                | SectionKind::Lines
                | SectionKind::Failure
                | SectionKind::Unsupported
        )
    }
}

/// One section of the deck.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// What the section is.
    pub kind: SectionKind,
    /// The section title as written (`LINE TYPES`), and its span.
    pub title: Token,
    /// Column names, when the section had a column-name row.
    pub columns: Vec<Token>,
    /// The data rows.
    pub rows: Vec<Row>,
}

/// A lexed deck.
#[derive(Clone, Debug, PartialEq)]
pub struct Deck {
    /// Sections in file order.
    pub sections: Vec<Section>,
}

impl Deck {
    /// The first section of a kind.
    pub fn section(&self, kind: SectionKind) -> Option<&Section> {
        self.sections.iter().find(|s| s.kind == kind)
    }
}

/// Whether `source` looks like a MoorDyn input deck rather than a TOML scenario: a dashed
/// section header naming one of MoorDyn's sections.
pub fn looks_like_deck(source: &str) -> bool {
    source.lines().take(400).any(|l| {
        l.contains("---")
            && matches!(
                classify(l),
                Some((
                    SectionKind::LineTypes | SectionKind::Points | SectionKind::Lines,
                    _
                ))
            )
    })
}

/// Classifies a header line: the section and the title text (dashes trimmed); `None` for a
/// line that is not a section header. The closing line is `Some((Unsupported, "END"))`-like:
/// see [`is_closing`].
fn classify(line: &str) -> Option<(SectionKind, String)> {
    if !line.contains("---") {
        return None;
    }
    let title = line
        .trim()
        .trim_matches(|c: char| c == '-' || c.is_whitespace())
        .to_string();
    let u = title.to_uppercase();
    if u.contains("MOORDYN") {
        return None; // the banner `---- MoorDyn Input File ----` above the description
    }
    let has = |k: &str| u.contains(k);
    let kind = if has("LINE DICTIONARY") || has("LINE TYPES") {
        SectionKind::LineTypes
    } else if has("ROD DICTIONARY") || has("ROD TYPES") {
        SectionKind::RodTypes
    } else if has("BODY LIST") || has("BODY PROPERTIES") || has("BODIES") {
        SectionKind::Bodies
    } else if has("ROD LIST") || has("ROD PROPERTIES") || has("RODS") {
        SectionKind::Rods
    } else if has("POINT LIST")
        || has("POINT PROPERTIES")
        || has("POINTS")
        || has("CONNECTION PROPERTIES")
        || has("NODE PROPERTIES")
    {
        SectionKind::Points
    } else if has("LINE LIST") || has("LINE PROPERTIES") || has("LINES") {
        SectionKind::Lines
    } else if has("FAILURE") {
        SectionKind::Failure
    } else if has("OPTIONS") {
        SectionKind::Options
    } else if has("OUTPUT") {
        SectionKind::Outputs
    } else {
        SectionKind::Unsupported
    };
    Some((kind, title))
}

/// The closing line: `--- need this line ---`, `--- END ---` or a line of dashes alone.
fn is_closing(title: &str) -> bool {
    let u = title.to_uppercase();
    u.is_empty() || u.contains("NEED THIS LINE") || u.split_whitespace().any(|w| w == "END")
}

fn words(source: &str, start: usize, line: &str) -> Vec<Token> {
    let mut out = Vec::new();
    let mut word: Option<usize> = None;
    for (i, c) in line.char_indices() {
        let sep = c.is_whitespace() || c == ',';
        match (sep, word) {
            (true, Some(w)) => {
                out.push(Token {
                    text: line[w..i].to_string(),
                    span: start + w..start + i,
                });
                word = None;
            }
            (false, None) => word = Some(i),
            _ => {}
        }
    }
    if let Some(w) = word {
        out.push(Token {
            text: line[w..].to_string(),
            span: start + w..start + line.len(),
        });
    }
    debug_assert!(
        out.iter()
            .all(|t| source.get(t.span.clone()) == Some(&t.text[..]))
    );
    out
}

/// Whether a row is a column-name row of a table: its first word is a column title MoorDyn
/// decks use (`TypeName`, `Name`, `ID`, `LineType`, `Node`, `Point`, `Line`, ...).
fn is_column_row(tokens: &[Token]) -> bool {
    let Some(first) = tokens.first() else {
        return false;
    };
    let f = first.text.to_lowercase();
    [
        "typename",
        "name",
        "id",
        "linetype",
        "node",
        "point",
        "line",
        "rod",
        "body",
        "con",
        "#",
        "failureid",
    ]
    .iter()
    .any(|k| f == *k || (f.starts_with(k) && f.len() <= k.len() + 1))
        && tokens.iter().all(|t| t.text.parse::<f64>().is_err())
}

/// Whether a row is a unit row: every word in parentheses (`(m)`, `(kg/m)`, `(-)`), or
/// units with spaces inside their parentheses (FAILURE's `(s or 0)`): the row starts with `(`
/// and ends with `)`.
fn is_unit_row(tokens: &[Token]) -> bool {
    !tokens.is_empty() && tokens.iter().all(|t| t.text.starts_with('('))
        || tokens.first().is_some_and(|t| t.text.starts_with('('))
            && tokens.last().is_some_and(|t| t.text.ends_with(')'))
}

/// Splits a deck into sections. Errors: a table row before any section, no closing line.
pub fn lex(file: &Path, source: &str) -> Result<Deck, Box<Diagnostic>> {
    let mut sections: Vec<Section> = Vec::new();
    let mut offset = 0;
    let mut closed = false;
    let mut expect_columns = false;
    let mut expect_units = false;
    for (n, raw) in source.split_inclusive('\n').enumerate() {
        let start = offset;
        offset += raw.len();
        let line = raw.trim_end_matches(['\n', '\r']);
        if let Some((kind, title)) = classify(line) {
            if is_closing(&title) {
                closed = true;
                break;
            }
            let at = line.find(title.as_str()).unwrap_or(0);
            sections.push(Section {
                kind,
                title: Token {
                    text: title.clone(),
                    span: start + at..start + at + title.len(),
                },
                columns: Vec::new(),
                rows: Vec::new(),
            });
            expect_columns = kind.is_table();
            expect_units = kind.is_table();
            continue;
        }
        let tokens = words(source, start, line);
        if tokens.is_empty() {
            continue;
        }
        let Some(section) = sections.last_mut() else {
            continue; // title and description text before the first section
        };
        if expect_columns && is_column_row(&tokens) {
            section.columns = tokens;
            expect_columns = false;
            continue;
        }
        expect_columns = false;
        if expect_units && is_unit_row(&tokens) {
            expect_units = false;
            continue;
        }
        expect_units = false;
        section.rows.push(Row {
            line: n + 1,
            span: start..start + line.len(),
            tokens,
        });
    }
    if !closed {
        let end = source.len();
        return Err(Box::new(Diagnostic::new(
            file,
            source,
            Some(end..end),
            "",
            "the deck ends without its closing line",
        )
        .value("end of file")
        .expected("a last line of dashes such as `------- need this line -------` or `--- END ---`")
        .hint(
            "MoorDyn decks end with a dashed closing line; a deck without one may have been cut \
             short: check that the file is complete and add the line",
        )));
    }
    Ok(Deck { sections })
}
