//! Input errors that name the file, line and column, the key, the bad value, what was
//! expected (unit and range) and a hint, rendered with the offending source line.

use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};

/// One problem in an input file.
#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    /// File.
    pub file: PathBuf,
    /// Byte span in the file, if known.
    pub span: Option<Range<usize>>,
    /// 1-based line and column of the span start.
    pub line: usize,
    /// 1-based column.
    pub column: usize,
    /// Dotted key path, e.g. `line_types[0].diameter`.
    pub key: String,
    /// The value as written (empty when missing).
    pub value: String,
    /// What is wrong.
    pub message: String,
    /// What was expected: unit and range.
    pub expected: String,
    /// How to fix it.
    pub hint: String,
    source_line: String,
    /// Width of the underline: the span's first line, in characters.
    width: usize,
}

impl Diagnostic {
    /// A diagnostic at `span` of `source`. Locating it scans `source` up to the span: for
    /// many diagnostics in one source, use [`Diagnostic::indexed`].
    pub fn new(
        file: &Path,
        source: &str,
        span: Option<Range<usize>>,
        key: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        let at = span.as_ref().map(|s| locate(source, s.start));
        Self::located(file, source, at, span, key, message)
    }

    /// [`Diagnostic::new`] located through `index`, the [`LineIndex`] of `source`: in time
    /// O(log lines) (plus the length of the line for a line with non-ASCII text before the
    /// span), so that n diagnostics cost O(n log n), not O(n × size).
    pub fn indexed(
        file: &Path,
        source: &str,
        index: &LineIndex,
        span: Option<Range<usize>>,
        key: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        let at = span.as_ref().map(|s| index.locate(source, s.start));
        Self::located(file, source, at, span, key, message)
    }

    fn located(
        file: &Path,
        source: &str,
        at: Option<(usize, usize, String)>,
        span: Option<Range<usize>>,
        key: impl Into<String>,
        message: impl Into<String>,
    ) -> Self {
        let (line, column, source_line) = at.unwrap_or((0, 0, String::new()));
        let value = span
            .clone()
            .and_then(|s| source.get(s))
            .and_then(|v| v.lines().next())
            .unwrap_or("")
            .to_string();
        let width = value.chars().count().max(1);
        Self {
            file: file.to_path_buf(),
            span,
            line,
            column,
            key: key.into(),
            value,
            message: message.into(),
            expected: String::new(),
            hint: String::new(),
            source_line,
            width,
        }
    }
    /// Sets the expected unit and range.
    pub fn expected(mut self, e: impl Into<String>) -> Self {
        self.expected = e.into();
        self
    }
    /// Sets the hint.
    pub fn hint(mut self, h: impl Into<String>) -> Self {
        self.hint = h.into();
        self
    }
    /// Overrides the value text.
    pub fn value(mut self, v: impl Into<String>) -> Self {
        self.value = v.into();
        self
    }
}

/// 1-based line of a byte offset in `source` (clamped to its end).
pub fn line_number(source: &str, offset: usize) -> usize {
    let end = offset.min(source.len());
    #[cfg(test)]
    work::add(end);
    source.as_bytes()[..end]
        .iter()
        .filter(|&&c| c == b'\n')
        .count()
        + 1
}

/// The start of every line of a source, to locate many offsets in it: built in one pass
/// over the source, then each offset's line by binary search.
#[derive(Clone, Debug)]
pub struct LineIndex {
    /// Byte offset of the start of each line (the first is 0).
    starts: Vec<usize>,
    /// Whether each line is ASCII only (its columns are then byte differences).
    ascii: Vec<bool>,
    /// Length of the source [bytes].
    len: usize,
}

impl LineIndex {
    /// The index of `source`.
    pub fn new(source: &str) -> Self {
        let mut starts = vec![0];
        let mut ascii = Vec::new();
        let mut line_ascii = true;
        for (i, &c) in source.as_bytes().iter().enumerate() {
            if c == b'\n' {
                starts.push(i + 1);
                ascii.push(line_ascii);
                line_ascii = true;
            } else if !c.is_ascii() {
                line_ascii = false;
            }
        }
        ascii.push(line_ascii);
        #[cfg(test)]
        work::add(source.len());
        Self {
            starts,
            ascii,
            len: source.len(),
        }
    }

    /// 1-based line of a byte offset (clamped to the end): [`line_number`] in O(log lines).
    pub fn line(&self, offset: usize) -> usize {
        let offset = offset.min(self.len);
        self.starts.partition_point(|&s| s <= offset)
    }

    /// (line, column, text of the line) at `offset`, as [`locate`] gives them.
    fn locate(&self, source: &str, offset: usize) -> (usize, usize, String) {
        let offset = offset.min(source.len());
        let line = self.line(offset);
        let start = self.starts[line - 1];
        let column = if self.ascii[line - 1] {
            offset - start + 1
        } else {
            #[cfg(test)]
            work::add(offset - start);
            source[start..offset].chars().count() + 1
        };
        let end = match self.starts.get(line) {
            Some(&next) => next - 1,
            None => source.len(),
        };
        #[cfg(test)]
        work::add(end - start);
        (
            line,
            column,
            source[start..end].trim_end_matches('\r').to_string(),
        )
    }
}

/// A count of the work done to locate diagnostics and write their hints (bytes scanned,
/// sources parsed), per thread, for the tests that check it grows linearly with the number of
/// errors.
#[cfg(test)]
pub(crate) mod work {
    use std::cell::Cell;
    thread_local!(static WORK: Cell<usize> = const { Cell::new(0) });
    /// Counts `n` units of work.
    pub fn add(n: usize) {
        WORK.with(|w| w.set(w.get() + n));
    }
    /// The work counted on this thread so far.
    pub fn done() -> usize {
        WORK.with(|w| w.get())
    }
}

fn locate(source: &str, offset: usize) -> (usize, usize, String) {
    let offset = offset.min(source.len());
    #[cfg(test)]
    work::add(offset);
    let before = &source[..offset];
    let line = line_number(source, offset);
    let start = before.rfind('\n').map(|i| i + 1).unwrap_or(0);
    let column = source[start..offset].chars().count() + 1;
    let end = source[start..]
        .find('\n')
        .map(|i| start + i)
        .unwrap_or(source.len());
    (
        line,
        column,
        source[start..end].trim_end_matches('\r').to_string(),
    )
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "error: {}", self.message)?;
        if self.line > 0 {
            writeln!(
                f,
                "  --> {}:{}:{}",
                self.file.display(),
                self.line,
                self.column
            )?;
            let num = self.line.to_string();
            let pad = " ".repeat(num.len());
            writeln!(f, "{pad} |")?;
            writeln!(f, "{num} | {}", self.source_line)?;
            let width = self.width;
            writeln!(
                f,
                "{pad} | {}{}",
                " ".repeat(self.column - 1),
                "^".repeat(width)
            )?;
        } else {
            writeln!(f, "  --> {}", self.file.display())?;
        }
        if !self.key.is_empty() {
            writeln!(f, "  = key: {}", self.key)?;
        }
        if !self.value.is_empty() {
            writeln!(f, "  = value: {}", self.value)?;
        }
        if !self.expected.is_empty() {
            writeln!(f, "  = expected: {}", self.expected)?;
        }
        if !self.hint.is_empty() {
            write!(f, "  = hint: {}", self.hint)?;
        }
        Ok(())
    }
}

/// All problems found in a file (at least one).
#[derive(Clone, Debug, PartialEq)]
pub struct ScenarioError {
    /// The problems, in file order.
    pub diagnostics: Vec<Diagnostic>,
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, d) in self.diagnostics.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
                writeln!(f)?;
            }
            write!(f, "{d}")?;
        }
        if self.diagnostics.len() > 1 {
            write!(
                f,
                "\n\n{} errors in {}",
                self.diagnostics.len(),
                self.diagnostics[0].file.display()
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for ScenarioError {}

impl From<Diagnostic> for ScenarioError {
    fn from(d: Diagnostic) -> Self {
        Self {
            diagnostics: vec![d],
        }
    }
}

/// Edit distance for "did you mean" hints.
pub fn closest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let dist = |a: &str, b: &str| {
        let b: Vec<char> = b.chars().collect();
        let mut prev: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.chars().enumerate() {
            let mut cur = vec![i + 1];
            for (j, cb) in b.iter().enumerate() {
                cur.push(
                    (prev[j] + usize::from(ca != *cb))
                        .min(prev[j + 1] + 1)
                        .min(cur[j] + 1),
                );
            }
            prev = cur;
        }
        prev[b.len()]
    };
    candidates
        .into_iter()
        .map(|c| (dist(word, c), c))
        .filter(|(d, c)| *d <= (c.len() / 3).max(2))
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The index locates every offset as the scan does: line, column (in characters) and the
    /// line's text, across CRLF line ends, non-ASCII text, empty lines and the end.
    #[test]
    fn the_line_index_locates_as_the_scan() {
        let source = "a = 1\r\n\n# ünïcode ∑\nb = \"é\" # x\n\nlast";
        let index = LineIndex::new(source);
        for offset in
            (0..=source.len() + 2).filter(|&o| source.is_char_boundary(o.min(source.len())))
        {
            assert_eq!(
                index.locate(source, offset),
                locate(source, offset),
                "at {offset}"
            );
            assert_eq!(
                index.line(offset),
                line_number(source, offset),
                "at {offset}"
            );
        }
        let empty = LineIndex::new("");
        assert_eq!(empty.locate("", 0), locate("", 0));
    }
}
