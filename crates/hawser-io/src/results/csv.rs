//! The CSV files of a run (`timeseries.csv`, `snapshots/LINE.csv`): numbers in shortest
//! round-trip form, sample times from the sample counter, rows handed to the file whole, and
//! the reader every hawser tool uses, which drops a torn last line.

use hawser::math::Real;
use hawser::model::{Settings, TimeStep};
use std::fmt::Write as _;
use std::fs::File;
use std::io::{BufRead, BufReader, Seek, SeekFrom, Write};
use std::path::{Path, PathBuf};

/// Appends `x` to `out` in its shortest round-trip form (the fewest digits that parse back to
/// the same f64), as Python's `repr` writes floats: plain decimals for 1e-4 ≤ |x| < 1e16,
/// with `.0` on whole numbers so that every reader takes the column for floats (`0.1`,
/// `40.0`, `-0.0`, `53091.78098399729`), exponent form outside that range
/// (`1.0076310248122385e-14`, `2.5e16`). Non-finite values are `NaN`, `inf`, `-inf`. Rust's
/// `Debug` form of f64 is exactly this. Does not allocate once `out` has room.
pub fn push_number(out: &mut String, x: Real) {
    // `write!` into a String cannot fail.
    let _ = write!(out, "{x:?}");
}

/// Sample times from the sample counter: t_k = k × Δt_s, with the sampling interval Δt_s as
/// the decimal the scenario gives (`output_interval`, or with a fixed `time_step` that does
/// not divide it, the step times the steps per sample), so that sample 3 of a 0.1 s interval
/// is written 0.3 and not 0.30000000000000004 (3 × 0.1 in binary arithmetic, what the clock
/// holds). Each time is the f64 nearest the exact decimal k × Δt_s.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SampleTimes {
    /// Δt_s = `digits` × 10^`exponent` exactly; `None` when it has no short decimal form (the
    /// clock's times are written as they are).
    decimal: Option<(u64, i32)>,
    /// Δt_s [s] as the clock holds it.
    interval: Real,
}

impl SampleTimes {
    /// The sample times of a run with `settings` whose stepper took `step` [s] and samples
    /// every `interval` [s] ([`hawser::Session::step_size`], [`hawser::Session::sample_interval`]).
    pub fn new(settings: &Settings, step: Real, interval: Real) -> Self {
        let oi = settings.output_interval;
        let decimal = if (interval - oi).abs() <= 1e-9 * oi {
            decimal_of(oi)
        } else if let TimeStep::Fixed(dt) = settings.time_step
            && dt == step
        {
            let per_sample = (interval / dt).round();
            decimal_of(dt).and_then(|(d, e)| Some((d.checked_mul(per_sample as u64)?, e)))
        } else {
            None
        };
        Self { decimal, interval }
    }

    /// The time [s] of sample `index` taken at clock time `clock` [s]: the f64 nearest
    /// `index` × Δt_s, or `clock` itself when that is more than 1e-6 Δt_s away (a sample off
    /// the regular grid, which a coupling host's uneven steps can make) or has no short
    /// decimal form.
    pub fn time(&self, index: u64, clock: Real) -> Real {
        if let Some((digits, exponent)) = self.decimal
            && let Some(n) = (digits as u128).checked_mul(index as u128)
            // n and 10^|e| are exact in f64: one correctly rounded operation gives the f64
            // nearest n × 10^e.
            && n < (1u128 << 53)
            && exponent.abs() <= 22
        {
            let p = 10f64.powi(exponent.abs());
            let t = if exponent < 0 {
                n as f64 / p
            } else {
                n as f64 * p
            };
            if (t - clock).abs() <= 1e-6 * self.interval {
                return t;
            }
        }
        clock
    }
}

/// The shortest decimal form of `x` > 0 as (digits, power of ten), when the digits fit a u64.
fn decimal_of(x: Real) -> Option<(u64, i32)> {
    if !(x > 0.0 && x.is_finite()) {
        return None;
    }
    let s = format!("{x:e}");
    let (mantissa, exponent) = s.split_once('e')?;
    let exponent: i32 = exponent.parse().ok()?;
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let digits: u64 = format!("{whole}{fraction}").parse().ok()?;
    Some((digits, exponent - fraction.len() as i32))
}

/// Where a [`RowWriter`] writes: a file, which can be cut back to a length.
pub trait RowSink: Write {
    /// Cuts the output back to its first `len` bytes and goes on writing there.
    fn cut_back(&mut self, len: u64) -> std::io::Result<()>;
}

impl RowSink for File {
    fn cut_back(&mut self, len: u64) -> std::io::Result<()> {
        self.set_len(len)?;
        self.seek(SeekFrom::Start(len)).map(|_| ())
    }
}

/// A CSV file written by rows: each row is formatted whole in memory and handed to the file in
/// one write call, newline last, on [`RowWriter::commit`]. A process killed between two rows
/// (even by SIGKILL) leaves whole rows only; killed inside the write call, it leaves a last
/// line without its newline, which [`TableReader`] drops. A write that fails part way (a full
/// disk, a file-size limit) is cut back to the last whole row. Every error names the file.
pub struct RowWriter<W: RowSink = File> {
    path: PathBuf,
    out: W,
    buf: String,
    /// Bytes handed to `out` so far (the file's length when it was created or cut back).
    len: u64,
}

impl RowWriter<File> {
    /// Creates (or truncates) `path` and writes `header` (the column names, comma-separated)
    /// at once, so that a file system that cannot take it (full, read-only, over quota) is
    /// found before the run starts, with the file's name.
    pub fn create<'a>(
        path: &Path,
        header: impl IntoIterator<Item = &'a str>,
    ) -> std::io::Result<Self> {
        let out = File::create(path).map_err(|e| cannot("create", path, e))?;
        let mut w = Self::new(path, out, 0);
        for name in header {
            w.text(name);
        }
        w.end_row();
        w.commit()?;
        Ok(w)
    }

    /// Reopens `path` to append after its first `len` bytes (a run resumed from a checkpoint
    /// taken when the file was that long): what came later is cut off and written again.
    pub fn reopen(path: &Path, len: u64) -> std::io::Result<Self> {
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .map_err(|e| cannot("open", path, e))?;
        let now = f.metadata().map_err(|e| cannot("read", path, e))?.len();
        if now < len {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!(
                    "{} has {now} bytes, but the checkpoint says {len}: it was changed since",
                    path.display()
                ),
            ));
        }
        f.set_len(len).map_err(|e| cannot("cut back", path, e))?;
        f.seek(SeekFrom::End(0))
            .map_err(|e| cannot("seek in", path, e))?;
        Ok(Self::new(path, f, len))
    }
}

impl<W: RowSink> RowWriter<W> {
    /// A writer on `out`, which already holds `len` bytes of `path`.
    pub fn new(path: &Path, out: W, len: u64) -> Self {
        Self {
            path: path.to_path_buf(),
            out,
            buf: String::new(),
            len,
        }
    }

    fn separate(&mut self) {
        if !(self.buf.is_empty() || self.buf.ends_with('\n')) {
            self.buf.push(',');
        }
    }

    /// Adds a number field to the current row ([`push_number`]).
    pub fn number(&mut self, x: Real) {
        self.separate();
        push_number(&mut self.buf, x);
    }

    /// Adds an integer field to the current row.
    pub fn integer(&mut self, i: u64) {
        self.separate();
        let _ = write!(self.buf, "{i}");
    }

    /// Adds a text field to the current row, as it is (column names; hawser's names hold no
    /// comma, quote or newline).
    pub fn text(&mut self, s: &str) {
        self.separate();
        self.buf.push_str(s);
    }

    /// Ends the current row.
    pub fn end_row(&mut self) {
        self.buf.push('\n');
    }

    /// Hands the rows ended since the last commit to the file in one write call. When that
    /// fails, the part of them that was written is cut off again (cutting back takes no
    /// space), so the file ends with its last whole row.
    pub fn commit(&mut self) -> std::io::Result<()> {
        debug_assert!(self.buf.is_empty() || self.buf.ends_with('\n'));
        if let Err(e) = self
            .out
            .write_all(self.buf.as_bytes())
            .and_then(|()| self.out.flush())
        {
            let _ = self.out.cut_back(self.len);
            return Err(cannot("write", &self.path, e));
        }
        self.len += self.buf.len() as u64;
        self.buf.clear();
        Ok(())
    }

    /// Bytes written to the file so far (its length after the last commit).
    pub fn len(&self) -> u64 {
        self.len
    }

    /// Whether nothing was written.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The file's path.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

/// An I/O error that names the file and what could not be done with it.
pub(crate) fn cannot(what: &str, path: &Path, e: std::io::Error) -> std::io::Error {
    std::io::Error::new(e.kind(), format!("cannot {what} {}: {e}", path.display()))
}

/// Reads a CSV table of numbers as hawser writes them, row by row with bounded memory: the
/// header's column names, then one row of f64 at a time. A last line without its newline (a
/// run killed while writing it, or a file read while a run is writing it) is not returned:
/// [`TableReader::torn`] says it was dropped.
pub struct TableReader {
    path: PathBuf,
    reader: BufReader<File>,
    names: Vec<String>,
    line: String,
    row: Vec<Real>,
    line_number: usize,
    torn: bool,
}

impl TableReader {
    /// Opens `path` and reads its header.
    pub fn open(path: &Path) -> std::io::Result<Self> {
        let file = File::open(path).map_err(|e| cannot("open", path, e))?;
        let mut r = Self {
            path: path.to_path_buf(),
            reader: BufReader::new(file),
            names: Vec::new(),
            line: String::new(),
            row: Vec::new(),
            line_number: 0,
            torn: false,
        };
        if !r.read_line()? {
            return Err(r.invalid(if r.torn {
                "its header line is incomplete"
            } else {
                "it is empty (no header line)"
            }));
        }
        r.names = r.line.trim_end().split(',').map(str::to_string).collect();
        Ok(r)
    }

    /// Reads the next whole line into `self.line`; false at the end (and at a torn last line).
    fn read_line(&mut self) -> std::io::Result<bool> {
        self.line.clear();
        let n = self
            .reader
            .read_line(&mut self.line)
            .map_err(|e| cannot("read", &self.path, e))?;
        if n == 0 {
            return Ok(false);
        }
        self.line_number += 1;
        if !self.line.ends_with('\n') {
            self.torn = true;
            return Ok(false);
        }
        Ok(true)
    }

    fn invalid(&self, why: &str) -> std::io::Error {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("{}:{}: {why}", self.path.display(), self.line_number),
        )
    }

    /// The column names of the header.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The next row, or `None` after the last whole line.
    pub fn next_row(&mut self) -> std::io::Result<Option<&[Real]>> {
        if !self.read_line()? {
            return Ok(None);
        }
        self.row.clear();
        for (column, field) in self.line.trim_end().split(',').enumerate() {
            match field.parse::<Real>() {
                Ok(x) => self.row.push(x),
                Err(_) => {
                    return Err(self.invalid(&format!(
                        "column {} ({}): `{field}` is not a number",
                        column + 1,
                        self.names.get(column).map_or("beyond the header", |s| s)
                    )));
                }
            }
        }
        if self.row.len() != self.names.len() {
            return Err(self.invalid(&format!(
                "{} fields, the header has {}",
                self.row.len(),
                self.names.len()
            )));
        }
        Ok(Some(&self.row))
    }

    /// Whether a last line without its newline was found and dropped.
    pub fn torn(&self) -> bool {
        self.torn
    }
}

/// A whole CSV table of numbers: column names and columns.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Table {
    /// Column names, in file order.
    pub names: Vec<String>,
    /// One vector per column, in file order, each with one value per row.
    pub columns: Vec<Vec<Real>>,
    /// Whether a torn last line (without its newline) was dropped.
    pub torn: bool,
}

impl Table {
    /// The column named `name`.
    pub fn column(&self, name: &str) -> Option<&[Real]> {
        let i = self.names.iter().position(|n| n == name)?;
        Some(&self.columns[i])
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.columns.first().map_or(0, Vec::len)
    }
}

/// Reads a whole table ([`TableReader`]): `timeseries.csv`, or a line's snapshots.
pub fn read_table(path: &Path) -> std::io::Result<Table> {
    let mut r = TableReader::open(path)?;
    let mut columns = vec![Vec::new(); r.names().len()];
    while let Some(row) = r.next_row()? {
        for (c, x) in columns.iter_mut().zip(row) {
            c.push(*x);
        }
    }
    Ok(Table {
        names: r.names().to_vec(),
        columns,
        torn: r.torn(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shown(x: f64) -> String {
        let mut s = String::new();
        push_number(&mut s, x);
        s
    }

    #[test]
    fn numbers_are_written_as_python_writes_them() {
        assert_eq!(shown(0.1), "0.1");
        assert_eq!(shown(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(shown(53091.780990789564), "53091.780990789564");
        assert_eq!(shown(0.0), "0.0");
        assert_eq!(shown(-0.0), "-0.0");
        assert_eq!(shown(40.0), "40.0");
        assert_eq!(shown(1e-4), "0.0001");
        assert_eq!(shown(9.9e-5), "9.9e-5");
        assert_eq!(shown(1e15), "1000000000000000.0");
        assert_eq!(shown(1e16), "1e16");
        assert_eq!(shown(-1.0076310248122385e-14), "-1.0076310248122385e-14");
        assert_eq!(shown(7.016050867430034e-39), "7.016050867430034e-39");
        assert_eq!(shown(123456789012345.6), "123456789012345.6");
        assert_eq!(shown(2.5e16), "2.5e16");
        assert_eq!(shown(f64::NAN), "NaN");
        assert_eq!(shown(f64::INFINITY), "inf");
        assert_eq!(shown(f64::NEG_INFINITY), "-inf");
        // Every form parses back to the same bits.
        let mut x = 1.234_567_890_123_456_7e-300;
        while x < 1e300 {
            for v in [x, -x, x * 0.1 + 3.0, 1.0 / x] {
                assert_eq!(
                    shown(v).parse::<f64>().unwrap().to_bits(),
                    v.to_bits(),
                    "{v}"
                );
            }
            x *= 7.3;
        }
    }

    #[test]
    fn sample_times_are_the_decimal_multiples_of_the_interval() {
        let settings = Settings {
            output_interval: 0.1,
            ..Default::default()
        };
        // Auto: the step divides the output interval (0.1 / 3 three times is not exactly 0.1).
        let step = 0.1 / 3.0;
        let interval = step * 3.0;
        let times = SampleTimes::new(&settings, step, interval);
        assert_eq!(3.0 * interval, 0.30000000000000004);
        assert_eq!(times.time(3, 3.0 * interval), 0.3);
        assert_eq!(times.time(9, 9.0 * interval), 0.9);
        assert_eq!(
            times.time(123_456_789, 123_456_789.0 * interval),
            12_345_678.9
        );
        // A sample off the grid keeps the clock's time.
        assert_eq!(times.time(3, 0.31), 0.31);
        // A fixed step that does not divide the output interval: 33 steps of 0.003 s.
        let fixed = Settings {
            output_interval: 0.1,
            time_step: TimeStep::Fixed(0.003),
            ..Default::default()
        };
        let times = SampleTimes::new(&fixed, 0.003, 33.0 * 0.003);
        assert_eq!(times.time(7, 7.0 * 33.0 * 0.003), 0.693);
        // An interval without a short decimal form: the clock's times.
        let third = Settings {
            output_interval: 1.0 / 3.0,
            ..Default::default()
        };
        let times = SampleTimes::new(&third, 1.0 / 30.0, 1.0 / 3.0);
        assert_eq!(times.time(100, 100.0 / 3.0), 100.0 / 3.0);
    }

    /// A sink that records the byte ranges of each write call.
    struct Calls(Vec<Vec<u8>>);

    impl Write for Calls {
        fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
            self.0.push(b.to_vec());
            Ok(b.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    impl RowSink for Calls {
        fn cut_back(&mut self, _: u64) -> std::io::Result<()> {
            unreachable!("no write fails")
        }
    }

    /// A sink that takes `room` bytes and then fails, as a full disk does, after taking part
    /// of the write that overflows it.
    struct Full {
        bytes: Vec<u8>,
        room: usize,
    }

    impl Write for Full {
        fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
            let n = b.len().min(self.room - self.bytes.len());
            if n == 0 {
                return Err(std::io::Error::from_raw_os_error(28));
            }
            self.bytes.extend_from_slice(&b[..n]);
            Ok(n)
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    impl RowSink for Full {
        fn cut_back(&mut self, len: u64) -> std::io::Result<()> {
            self.bytes.truncate(len as usize);
            Ok(())
        }
    }

    #[test]
    fn a_write_that_fails_part_way_leaves_whole_rows() {
        let mut w = RowWriter::new(
            Path::new("out/t.csv"),
            Full {
                bytes: Vec::new(),
                room: 30,
            },
            0,
        );
        let mut failed = None;
        for row in 0..10 {
            w.number(row as f64);
            w.number(1.0 / 3.0);
            w.end_row();
            if let Err(e) = w.commit() {
                failed = Some((row, e.to_string()));
                break;
            }
        }
        // "0.0,0.3333333333333333\n" is 23 bytes: the second row does not fit.
        let (row, e) = failed.expect("the sink is full");
        assert_eq!(row, 1);
        assert!(e.starts_with("cannot write out/t.csv: "), "{e}");
        assert_eq!(w.out.bytes, b"0.0,0.3333333333333333\n");
        assert_eq!(w.len(), 23);
    }

    #[test]
    fn each_commit_is_one_write_call_ending_in_a_newline() {
        // A row far longer than any buffer (20 000 fields, about 400 kB): still one call.
        let mut w = RowWriter::new(Path::new("t.csv"), Calls(Vec::new()), 0);
        for row in 0..3 {
            for i in 0..20_000 {
                w.number(row as f64 + i as f64 * 1.000_000_1e-7);
            }
            w.end_row();
            w.commit().unwrap();
        }
        let calls = &w.out.0;
        assert_eq!(calls.len(), 3);
        for c in calls {
            assert_eq!(c.iter().filter(|&&b| b == b'\n').count(), 1);
            assert_eq!(c.last(), Some(&b'\n'));
        }
        assert_eq!(w.len(), calls.iter().map(|c| c.len() as u64).sum::<u64>());
    }

    #[test]
    fn a_torn_last_line_is_dropped_and_flagged() {
        let dir = std::env::temp_dir().join(format!("hawser_csv_torn_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let p = dir.join("t.csv");
        std::fs::write(&p, "time,a\n0,1.5\n0.1,2.25\n0.2,3.12").unwrap();
        let t = read_table(&p).unwrap();
        assert!(t.torn);
        assert_eq!(t.names, ["time", "a"]);
        assert_eq!(t.column("a").unwrap(), [1.5, 2.25]);
        std::fs::write(&p, "time,a\n0,1.5\n").unwrap();
        assert!(!read_table(&p).unwrap().torn);
        std::fs::write(&p, "time,a\n0,x\n").unwrap();
        let e = read_table(&p).unwrap_err().to_string();
        assert!(e.contains("t.csv:2") && e.contains("column 2 (a)"), "{e}");
        std::fs::write(&p, "time,a\n0\n").unwrap();
        let e = read_table(&p).unwrap_err().to_string();
        assert!(e.contains("1 fields, the header has 2"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
