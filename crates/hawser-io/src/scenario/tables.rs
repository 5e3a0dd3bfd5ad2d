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
                    // The file may be no table at all: its contents are not quoted.
                    return Err(format!(
                        "{}: not an RAO table: its first line must be a header starting with \
                         `period_s`, `frequency_hz` or `omega_rad_s`",
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
            .map_err(|_| not_a_number(&at(n), &fields, !amplitudes.is_empty()))?;
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
                let at = format!("{}:{}", path.display(), n + 1);
                return Err(not_a_number(&at, &fields, !rows.is_empty()));
            }
        }
    }
    Ok(rows)
}

/// The error for a row of a table of numbers at `at` (file:line) whose `fields` are not all
/// numbers. The first bad field is quoted only when rows of numbers came before it (`table`):
/// a file that is not a table at all (a path mistyped into a password file, a key) has none
/// of its contents quoted.
fn not_a_number(at: &str, fields: &[&str], table: bool) -> String {
    let bad = fields.iter().find(|s| s.parse::<f64>().is_err());
    match bad {
        Some(b) if table => {
            let shown: String = b.chars().take(32).collect();
            let more = if b.chars().count() > 32 { "…" } else { "" };
            format!("{at}: not a number: `{}{more}`", shown.escape_debug())
        }
        _ => format!(
            "{at}: not a table of numbers (this line holds text where numbers were expected; \
             its contents are not shown)"
        ),
    }
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

/// A grid of seabed heights as read from a file: node coordinates x, y [m] (increasing) and
/// the heights z [m] (up, negative below the surface) with `z[j · x.len() + i]` at (x_i, y_j).
#[derive(Clone, Debug, PartialEq)]
pub struct HeightGrid {
    /// x of the nodes [m].
    pub x: Vec<f64>,
    /// y of the nodes [m].
    pub y: Vec<f64>,
    /// Heights [m].
    pub z: Vec<f64>,
}

/// Reads a seabed grid in any of three formats, told apart by their first lines:
///
/// - MoorDyn-C's `SeafloorFile`: a line `nx ny`, a line of the nx x values, a line of the ny
///   y values, then one line `x y z` per node, z the bed's height (negative below the
///   surface);
/// - MoorDyn-F's bathymetry file: a title line, `nGridX nx`, `nGridY ny`, a line of the nx x
///   values, then ny lines `y d₁ … d_nx` of depths (positive down);
/// - CSV: a header naming the columns `x`, `y` and `z` (height) or `depth` (positive down),
///   units in brackets allowed (`x [m]`), then one row per node in any order.
///
/// Every node of the grid needs exactly one value, on a grid value of x and y (MoorDyn leaves
/// this undefined); the error names the file and line.
pub fn read_seabed_grid(path: &Path) -> Result<HeightGrid, String> {
    let text = read_text_file(path).map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let at = |n: usize| format!("{}:{}", path.display(), n + 1);
    let lines: Vec<(usize, &str)> = text
        .lines()
        .enumerate()
        .map(|(n, l)| (n, l.trim()))
        .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
        .collect();
    let Some(&(first_line, first)) = lines.first() else {
        return Err(format!("{}: the file is empty", path.display()));
    };
    let numbers = |n: usize, line: &str| -> Result<Vec<f64>, String> {
        line.split([',', ';', '\t', ' '])
            .filter(|s| !s.is_empty())
            .map(|f| parse_number(f).ok_or_else(|| format!("{}: `{f}` is not a number", at(n))))
            .collect()
    };
    let counts = |line: &str| -> Option<Vec<usize>> {
        line.split_whitespace().map(|f| f.parse().ok()).collect()
    };
    // Nodes as (line, x, y, z).
    let mut nodes: Vec<(usize, f64, f64, f64)> = Vec::new();
    let (xs, ys): (Vec<f64>, Vec<f64>);
    if let Some(c) = counts(first).filter(|c| c.len() == 2) {
        // MoorDyn-C.
        let axis = |k: usize, count: usize, name: &str| -> Result<Vec<f64>, String> {
            let &(n, line) = lines.get(k).ok_or_else(|| {
                format!(
                    "{}: the line of the {count} {name} values is missing",
                    path.display()
                )
            })?;
            let v = numbers(n, line)?;
            if v.len() != count {
                return Err(format!(
                    "{}: {} {name} values, but the first line announces {count}",
                    at(n),
                    v.len()
                ));
            }
            Ok(v)
        };
        xs = axis(1, c[0], "x")?;
        ys = axis(2, c[1], "y")?;
        for &(n, line) in &lines[3.min(lines.len())..] {
            let v = numbers(n, line)?;
            if v.len() != 3 {
                return Err(format!(
                    "{}: expected `x y z`, found {} numbers",
                    at(n),
                    v.len()
                ));
            }
            nodes.push((n, v[0], v[1], v[2]));
        }
    } else if first.contains(',') {
        // CSV with a header.
        let names: Vec<String> = first
            .split(',')
            .map(|h| {
                h.split('[')
                    .next()
                    .unwrap_or("")
                    .trim()
                    .to_ascii_lowercase()
            })
            .collect();
        let column = |name: &str| names.iter().position(|h| h == name);
        let (Some(cx), Some(cy)) = (column("x"), column("y")) else {
            return Err(format!(
                "{}: the header needs columns `x`, `y` and `z` or `depth`, found `{first}`",
                at(first_line)
            ));
        };
        let (cz, sign) = match (column("z"), column("depth")) {
            (Some(c), None) => (c, 1.0),
            (None, Some(c)) => (c, -1.0),
            _ => {
                return Err(format!(
                    "{}: the header needs one column `z` (height, up) or `depth` (down), found `{first}`",
                    at(first_line)
                ));
            }
        };
        for &(n, line) in &lines[1..] {
            let v = numbers(n, line)?;
            if v.len() != names.len() {
                return Err(format!(
                    "{}: {} columns where the header names {}",
                    at(n),
                    v.len(),
                    names.len()
                ));
            }
            nodes.push((n, v[cx], v[cy], sign * v[cz]));
        }
        let axis = |pick: fn(&(usize, f64, f64, f64)) -> f64| {
            let mut a: Vec<f64> = nodes.iter().map(pick).collect();
            a.sort_by(f64::total_cmp);
            a.dedup();
            a
        };
        xs = axis(|r| r.1);
        ys = axis(|r| r.2);
    } else {
        // MoorDyn-F: a title, then nGridX and nGridY.
        let count = |k: usize, key: &str| -> Result<usize, String> {
            let &(n, line) = lines
                .get(k)
                .ok_or_else(|| format!("{}: the line `{key} N` is missing", path.display()))?;
            let mut f = line.split_whitespace();
            match (f.next(), f.next().and_then(|v| v.parse().ok())) {
                (Some(k), Some(v)) if k.eq_ignore_ascii_case(key) => Ok(v),
                _ => Err(format!(
                    "{}: expected `{key} N` (a MoorDyn-F bathymetry file), or a first line `nx ny` \
                     (MoorDyn-C), or a CSV header `x,y,z`; found `{line}`",
                    at(n)
                )),
            }
        };
        let nx = count(1, "nGridX")?;
        let ny = count(2, "nGridY")?;
        let &(n, line) = lines
            .get(3)
            .ok_or_else(|| format!("{}: the line of x values is missing", path.display()))?;
        xs = numbers(n, line)?;
        if xs.len() != nx {
            return Err(format!(
                "{}: {} x values, but nGridX is {nx}",
                at(n),
                xs.len()
            ));
        }
        let rows = &lines[4.min(lines.len())..];
        if rows.len() != ny {
            return Err(format!(
                "{}: {} rows of depths, but nGridY is {ny}",
                path.display(),
                rows.len()
            ));
        }
        let mut y = Vec::with_capacity(ny);
        for &(n, line) in rows {
            let v = numbers(n, line)?;
            if v.len() != nx + 1 {
                return Err(format!(
                    "{}: expected `y` and {nx} depths, found {} numbers",
                    at(n),
                    v.len()
                ));
            }
            y.push(v[0]);
            for (i, d) in v[1..].iter().enumerate() {
                nodes.push((n, xs[i], v[0], -d));
            }
        }
        ys = y;
    }
    for (name, axis) in [("x", &xs), ("y", &ys)] {
        if let Some(k) = axis.windows(2).position(|w| !(w[1] > w[0])) {
            return Err(format!(
                "{}: the {name} values must increase: {} then {}",
                path.display(),
                axis[k],
                axis[k + 1]
            ));
        }
    }
    let (nx, ny) = (xs.len(), ys.len());
    let mut z = vec![f64::NAN; nx * ny];
    for &(n, x, y, height) in &nodes {
        let find = |axis: &[f64], v: f64| axis.iter().position(|&a| a == v);
        let (Some(i), Some(j)) = (find(&xs, x), find(&ys, y)) else {
            return Err(format!(
                "{}: the node ({x}, {y}) is not on the grid's x and y values",
                at(n)
            ));
        };
        if !z[j * nx + i].is_nan() {
            return Err(format!("{}: the node ({x}, {y}) is given twice", at(n)));
        }
        z[j * nx + i] = height;
    }
    if let Some(k) = z.iter().position(|v| v.is_nan()) {
        return Err(format!(
            "{}: the node ({}, {}) has no height: give every node of the {nx} × {ny} grid",
            path.display(),
            xs[k % nx],
            ys[k / nx]
        ));
    }
    Ok(HeightGrid { x: xs, y: ys, z })
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

    /// The three grid formats read to the same grid; a node off the grid, a missing node and
    /// a count that does not match are refused with the file and line.
    #[test]
    fn seabed_grids_in_three_formats() {
        let c = temp("seafloor_c.txt");
        std::fs::write(
            &c,
            "3 2\n-10 0 10\n-5 5\n-10 -5 -40\n0 -5 -41\n10 -5 -42\n-10 5 -43\n0 5 -44\n10 5 -45\n",
        )
        .unwrap();
        let f = temp("bathymetry_f.txt");
        std::fs::write(
            &f,
            "--- MoorDyn Bathymetry Input File ---\nnGridX 3\nnGridY 2\n  -10 0 10\n-5 40 41 42\n5 43 44 45\n",
        )
        .unwrap();
        let csv = temp("grid.csv");
        std::fs::write(
            &csv,
            "x [m],y [m],depth [m]\n10,5,45\n-10,-5,40\n0,-5,41\n10,-5,42\n-10,5,43\n0,5,44\n",
        )
        .unwrap();
        let expected = HeightGrid {
            x: vec![-10.0, 0.0, 10.0],
            y: vec![-5.0, 5.0],
            z: vec![-40.0, -41.0, -42.0, -43.0, -44.0, -45.0],
        };
        for p in [&c, &f, &csv] {
            assert_eq!(read_seabed_grid(p).unwrap(), expected, "{}", p.display());
        }
        for (text, wanted) in [
            (
                "2 1\n0 1\n0\n0 0 -1\n0.5 0 -1\n",
                ":5: the node (0.5, 0) is not on the grid",
            ),
            ("2 1\n0 1\n0\n0 0 -1\n", "the node (1, 0) has no height"),
            (
                "3 1\n0 1\n0\n",
                ":2: 2 x values, but the first line announces 3",
            ),
            ("x,y,h\n0,0,1\n", "needs one column `z`"),
        ] {
            let p = temp("bad_grid.txt");
            std::fs::write(&p, text).unwrap();
            let e = read_seabed_grid(&p).unwrap_err();
            assert!(e.contains(wanted), "{e}");
        }
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
