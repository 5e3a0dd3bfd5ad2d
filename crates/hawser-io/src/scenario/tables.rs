//! Every file an input reads is read here, by the TOML builder and the MoorDyn deck reader
//! alike: the input file itself ([`read_text_file`]) and the files of numbers it refers to
//! (vessel-motion and point-motion tables, RAO tables, MoorDyn's tension–strain tables and
//! current profiles). Only regular files are read (a FIFO would block, a device such as
//! `/dev/zero` never end), and none larger than [`MAX_FILE_BYTES`].

use hawser::model::*;
use std::fmt;
use std::io::Read;
use std::path::Path;

/// Largest file hawser reads as input [bytes]: 256 MiB, some 30 times a 6-DOF motion table
/// sampled at 100 Hz for 3 hours. Larger files are refused before they are read.
pub const MAX_FILE_BYTES: u64 = 256 << 20;

/// Why a file could not be read.
#[derive(Debug)]
pub enum ReadError {
    /// The operating system's error (not found, permission denied, not UTF-8, …).
    Io(std::io::Error),
    /// Not a regular file: a directory, FIFO, socket or device (`what` says which).
    NotRegular {
        /// What the path is, e.g. "a FIFO (named pipe)".
        what: &'static str,
    },
    /// Larger than the limit.
    TooLarge {
        /// Its size [bytes] (at least; a file that grows while read may be larger).
        size: u64,
        /// The limit [bytes].
        limit: u64,
    },
}

impl ReadError {
    /// Whether the file exists but is refused (not regular, or too large).
    pub fn is_refused(&self) -> bool {
        !matches!(self, ReadError::Io(_))
    }
}

impl fmt::Display for ReadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ReadError::Io(e) => write!(f, "{e}"),
            ReadError::NotRegular { what } => write!(f, "it is {what}, not a regular file"),
            ReadError::TooLarge { size, limit } => write!(
                f,
                "it holds {size} bytes, above the limit of {limit} bytes ({} MiB) of an input file",
                limit >> 20
            ),
        }
    }
}

impl std::error::Error for ReadError {}

/// The text of the regular file `path`, of at most [`MAX_FILE_BYTES`].
pub fn read_text_file(path: &Path) -> Result<String, ReadError> {
    read_bounded(path, MAX_FILE_BYTES)
}

/// The text of the regular file `path`, of at most `limit` bytes. The kind is checked before
/// the file is opened (opening a FIFO blocks until a writer comes), and the read stops after
/// `limit + 1` bytes whatever size the file reports (files under `/proc` report 0).
fn read_bounded(path: &Path, limit: u64) -> Result<String, ReadError> {
    let regular = |m: &std::fs::Metadata| -> Result<(), ReadError> {
        let t = m.file_type();
        if t.is_file() {
            return Ok(());
        }
        Err(ReadError::NotRegular {
            what: file_kind(&t),
        })
    };
    let meta = std::fs::metadata(path).map_err(ReadError::Io)?;
    regular(&meta)?;
    if meta.len() > limit {
        return Err(ReadError::TooLarge {
            size: meta.len(),
            limit,
        });
    }
    let file = std::fs::File::open(path).map_err(ReadError::Io)?;
    regular(&file.metadata().map_err(ReadError::Io)?)?;
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    let read = file
        .take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(ReadError::Io)?;
    if read as u64 > limit {
        return Err(ReadError::TooLarge {
            size: read as u64,
            limit,
        });
    }
    String::from_utf8(bytes).map_err(|_| {
        ReadError::Io(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        ))
    })
}

/// What a file that is not regular is, in words.
fn file_kind(t: &std::fs::FileType) -> &'static str {
    if t.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_socket() {
            return "a socket";
        }
        if t.is_char_device() {
            return "a character device";
        }
        if t.is_block_device() {
            return "a block device";
        }
    }
    "not a file"
}

/// Reads an RAO table (docs/motions.md): `#` comments and blank lines skipped; a header line
/// whose first name is `period_s`, `frequency_hz` or `omega_rad_s` (the unit of the first
/// column), then rows of 14 numbers: wave period, frequency or angular frequency; heading
/// [deg]; amplitude and phase lag of surge, sway, heave [m/m, deg], roll, pitch, yaw [deg/m,
/// deg]. Rows are grouped by the first column in increasing order, each group listing the same
/// headings in increasing order. Errors name the file and line.
pub fn read_rao_table(path: &Path) -> Result<RaoTable, String> {
    use std::f64::consts::TAU;
    let text = read_text_file(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
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
                let list = |h: &[f64]| {
                    h.iter()
                        .map(|x| x.to_string())
                        .collect::<Vec<_>>()
                        .join(", ")
                };
                return Err(format!(
                    "{}: the rows for {v} list the headings {} [deg], but the first group lists \
                     {}: every period or frequency needs the same headings",
                    at(line),
                    list(group),
                    list(headings)
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

/// Reads a table of N numbers per row from a text file: columns separated by commas,
/// semicolons, tabs or spaces; blank lines, `#` comments and one header line are skipped.
/// `columns` names the columns for error messages.
pub fn read_table<const N: usize>(path: &Path, columns: &str) -> Result<Vec<[f64; N]>, String> {
    let text = read_text_file(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
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

/// Reads a MoorDyn tension–strain table: rows `strain tension` [-, N], whitespace or comma
/// separated, header lines skipped; a `(0, 0)` row is added when missing.
pub fn read_tension_strain(path: &Path) -> Result<Vec<[f64; 2]>, String> {
    let text = read_text_file(path).map_err(|e| format!("{}: {e}", path.display()))?;
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

/// Reads a MoorDyn current profile (`current_profile.txt`): rows `z ux uy uz` [m, m/s], header
/// lines (any line not all numbers) skipped; missing velocity components are 0. Rows in file
/// order.
pub fn read_current_profile(path: &Path) -> Result<Vec<[f64; 4]>, String> {
    let text = read_text_file(path).map_err(|e| e.to_string())?;
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
    Ok(rows)
}

/// Parses a number as MoorDyn does (C `atof`), accepting Fortran `D` exponents too.
pub fn parse_number(text: &str) -> Option<f64> {
    let t = text.replace(['d', 'D'], "e");
    t.parse::<f64>().ok().filter(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp(name: &str) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("hawser-tables-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    /// `/dev/zero` was read until memory ran out; a FIFO blocked for ever. Both are refused
    /// before they are opened, as is a directory.
    #[cfg(unix)]
    #[test]
    fn devices_fifos_and_directories_are_refused() {
        let e = read_text_file(Path::new("/dev/zero")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "it is a character device, not a regular file"
        );
        let fifo = temp("fifo");
        let _ = std::fs::remove_file(&fifo);
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if made.is_ok_and(|s| s.success()) {
            let e = read_text_file(&fifo).unwrap_err();
            assert_eq!(
                e.to_string(),
                "it is a FIFO (named pipe), not a regular file"
            );
            assert!(e.is_refused());
        }
        let e = read_text_file(&std::env::temp_dir()).unwrap_err();
        assert_eq!(e.to_string(), "it is a directory, not a regular file");
    }

    /// A file above the limit is refused from its size, before it is read (this one is
    /// sparse: 256 MiB + 1 byte of nothing), with its size and the limit in the message.
    #[test]
    fn files_above_the_limit_are_refused_unread() {
        let path = temp("big.csv");
        let f = std::fs::File::create(&path).unwrap();
        f.set_len(MAX_FILE_BYTES + 1).unwrap();
        let e = read_text_file(&path).unwrap_err();
        assert_eq!(
            e.to_string(),
            "it holds 268435457 bytes, above the limit of 268435456 bytes (256 MiB) of an input file"
        );
        std::fs::remove_file(&path).unwrap();
    }

    /// The read itself stops after limit + 1 bytes, whatever size the file reports (files
    /// under /proc report 0): here the limit is below the file's size.
    #[test]
    fn the_read_is_bounded() {
        let path = temp("small.csv");
        std::fs::write(&path, "0, 1, 2\n3, 4, 5\n").unwrap();
        assert_eq!(read_bounded(&path, 16).unwrap(), "0, 1, 2\n3, 4, 5\n");
        let e = read_bounded(&path, 15).unwrap_err();
        assert!(
            matches!(
                e,
                ReadError::TooLarge {
                    size: 16,
                    limit: 15
                }
            ),
            "{e}"
        );
        let missing = read_text_file(&temp("missing.csv")).unwrap_err();
        assert!(!missing.is_refused());
        std::fs::remove_file(&path).unwrap();
    }
}
