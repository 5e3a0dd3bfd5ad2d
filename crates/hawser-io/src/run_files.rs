//! Reading a run's files back: the time series (`timeseries.csv`) and the line snapshots
//! (`snapshots/LINE.csv`), for the statistics at the end of a run and for `hawser plot`, of a
//! finished or a running run (a row still being written is skipped).
//!
//! Column names are read by [`column_names`], the one place that knows the header's form:
//! names with their unit in brackets (`L1.end_b.tension [N]`), or plain names with the units
//! in a second header line (which is skipped: its first field is not a number) or in a
//! `channels.json` beside the file.

use hawser::math::Real;
use std::io::{BufRead, BufReader};
use std::path::Path;

/// A column's name and unit (empty when the file does not say).
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// Channel name without the unit, e.g. `L1.end_b.tension`.
    pub name: String,
    /// Unit, e.g. `N`.
    pub unit: String,
}

/// The columns of a CSV header `first` and the line after it, `second`: names without units,
/// units from the `[unit]` suffixes, else from `second` when it is a units line (its first
/// field is not a number), else from `channels` (the text of a `channels.json`: an object of
/// name → unit, or of name → {"unit": …}, or a list of {"name", "unit"}, at the top level or
/// under `"timeseries"` or `"channels"`). Returns the columns and whether `second` is a header line to skip.
pub fn column_names(
    first: &str,
    second: Option<&str>,
    channels: Option<&str>,
) -> (Vec<Column>, bool) {
    let fields: Vec<&str> = first.trim_end_matches(['\r', '\n']).split(',').collect();
    let mut columns: Vec<Column> = fields
        .iter()
        .map(|f| {
            let f = f.trim();
            match f.strip_suffix(']').and_then(|g| g.rsplit_once(" [")) {
                Some((name, unit)) => Column {
                    name: name.trim().to_string(),
                    unit: unit.to_string(),
                },
                None => Column {
                    name: f.to_string(),
                    unit: String::new(),
                },
            }
        })
        .collect();
    let units_line = second.filter(|s| {
        s.split(',')
            .next()
            .is_some_and(|f| !f.trim().is_empty() && f.trim().parse::<f64>().is_err())
    });
    if let Some(line) = units_line {
        let units: Vec<&str> = line.trim_end_matches(['\r', '\n']).split(',').collect();
        for (c, u) in columns.iter_mut().zip(units) {
            if c.unit.is_empty() {
                c.unit = u
                    .trim()
                    .trim_start_matches('[')
                    .trim_end_matches(']')
                    .to_string();
            }
        }
    }
    if let Some(text) = channels
        && let Ok(v) = serde_json::from_str::<serde_json::Value>(text)
    {
        let v = ["timeseries", "channels"]
            .iter()
            .find_map(|k| v.get(k).cloned())
            .unwrap_or(v);
        let unit_of = |name: &str| -> Option<String> {
            let u = match &v {
                serde_json::Value::Object(m) => m.get(name).map(|e| e.get("unit").unwrap_or(e)),
                serde_json::Value::Array(a) => a
                    .iter()
                    .find(|e| e.get("name").and_then(|n| n.as_str()) == Some(name))
                    .and_then(|e| e.get("unit")),
                _ => None,
            };
            u.and_then(|u| u.as_str()).map(str::to_string)
        };
        for c in columns.iter_mut().filter(|c| c.unit.is_empty()) {
            if let Some(u) = unit_of(&c.name) {
                c.unit = u;
            }
        }
    }
    (columns, units_line.is_some())
}

/// The header of a CSV file and a reader positioned at its first data row.
struct Csv {
    columns: Vec<Column>,
    lines: std::iter::Peekable<std::io::Lines<BufReader<std::fs::File>>>,
}

fn open_csv(path: &Path) -> std::io::Result<Csv> {
    let context =
        |e: std::io::Error| std::io::Error::new(e.kind(), format!("{}: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(context)?;
    let mut lines = BufReader::new(file).lines().peekable();
    let first = match lines.next() {
        Some(l) => l.map_err(context)?,
        None => {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!(
                    "{}: the file is empty (the run has not written its header yet)",
                    path.display()
                ),
            ));
        }
    };
    let second = match lines.peek() {
        Some(Ok(l)) => Some(l.clone()),
        _ => None,
    };
    let channels = path
        .parent()
        .and_then(|d| std::fs::read_to_string(d.join("channels.json")).ok());
    let (columns, skip) = column_names(&first, second.as_deref(), channels.as_deref());
    if skip {
        lines.next();
    }
    Ok(Csv { columns, lines })
}

impl Csv {
    /// Calls `row` with every complete row of numbers; a row with another number of fields
    /// or a field that is no number (the row a running run is writing) ends the reading.
    fn rows(self, path: &Path, mut row: impl FnMut(&[Real])) -> std::io::Result<()> {
        let n = self.columns.len();
        let mut values = vec![0.0; n];
        for line in self.lines {
            let line = line
                .map_err(|e| std::io::Error::new(e.kind(), format!("{}: {e}", path.display())))?;
            let mut k = 0;
            let mut ok = true;
            for f in line.split(',') {
                match (k < n).then(|| f.trim().parse::<Real>()) {
                    Some(Ok(v)) => values[k] = v,
                    _ => {
                        ok = false;
                        break;
                    }
                }
                k += 1;
            }
            if !ok || k != n {
                break;
            }
            row(&values);
        }
        Ok(())
    }
}

/// A run's time series in memory.
#[derive(Clone, Debug, Default)]
pub struct Timeseries {
    /// The channels (every column but time), in file order.
    pub channels: Vec<Column>,
    /// Sample times [s].
    pub time: Vec<Real>,
    /// `values[c][i]`: channel c at `time[i]`.
    pub values: Vec<Vec<Real>>,
}

impl Timeseries {
    /// Index of the channel named `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.channels.iter().position(|c| c.name == name)
    }

    /// Channel `c` as (time, value) pairs.
    pub fn points(&self, c: usize) -> Vec<(Real, Real)> {
        self.time
            .iter()
            .copied()
            .zip(self.values[c].iter().copied())
            .collect()
    }
}

/// The index of the time column among `columns` (the one named `time`; the first if none
/// is).
fn time_column(columns: &[Column]) -> usize {
    columns.iter().position(|c| c.name == "time").unwrap_or(0)
}

/// Streams the rows of `timeseries.csv` in `dir`: `row(time, channel values)` for each
/// complete row, channels in file order (the time column left out). Returns the channels.
pub fn for_each_sample(
    dir: &Path,
    mut row: impl FnMut(Real, &[Real]),
) -> std::io::Result<Vec<Column>> {
    let path = dir.join("timeseries.csv");
    let csv = open_csv(&path)?;
    let t = time_column(&csv.columns);
    let mut channels = csv.columns.clone();
    channels.remove(t);
    let mut values = vec![0.0; channels.len()];
    csv.rows(&path, |r| {
        let mut k = 0;
        for (j, &v) in r.iter().enumerate() {
            if j != t {
                values[k] = v;
                k += 1;
            }
        }
        row(r[t], &values)
    })?;
    Ok(channels)
}

/// Reads `timeseries.csv` in `dir` into memory.
pub fn read_timeseries(dir: &Path) -> std::io::Result<Timeseries> {
    let mut ts = Timeseries::default();
    let mut values: Vec<Vec<Real>> = Vec::new();
    ts.channels = for_each_sample(dir, |t, row| {
        if values.is_empty() {
            values = vec![Vec::new(); row.len()];
        }
        ts.time.push(t);
        for (c, &v) in values.iter_mut().zip(row) {
            c.push(v);
        }
    })?;
    if values.is_empty() {
        values = vec![Vec::new(); ts.channels.len()];
    }
    ts.values = values;
    Ok(ts)
}

/// One snapshot of a line: its nodes at one time.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Snapshot {
    /// Time [s].
    pub time: Real,
    /// Unstretched arc length of each node from end A [m].
    pub arc_length: Vec<Real>,
    /// Node positions [m].
    pub position: Vec<[Real; 3]>,
    /// Node tensions [N].
    pub tension: Vec<Real>,
}

/// Reads the snapshots of a line from `path` (`snapshots/LINE.csv`: one row per node per
/// snapshot, with columns `time`, `arc_length`, `x`, `y`, `z` and `tension`, found by name).
pub fn read_snapshots(path: &Path) -> std::io::Result<Vec<Snapshot>> {
    let csv = open_csv(path)?;
    let find = |name: &str| {
        csv.columns
            .iter()
            .position(|c| c.name == name)
            .ok_or_else(|| {
                std::io::Error::new(
                    std::io::ErrorKind::InvalidData,
                    format!("{}: no `{name}` column", path.display()),
                )
            })
    };
    let [t, s, x, y, z, tension] = [
        find("time")?,
        find("arc_length")?,
        find("x")?,
        find("y")?,
        find("z")?,
        find("tension")?,
    ];
    let mut out: Vec<Snapshot> = Vec::new();
    csv.rows(path, |r| {
        if out.last().is_none_or(|last| last.time != r[t]) {
            out.push(Snapshot {
                time: r[t],
                ..Default::default()
            });
        }
        let last = out.last_mut().expect("pushed");
        last.arc_length.push(r[s]);
        last.position.push([r[x], r[y], r[z]]);
        last.tension.push(r[tension]);
    })?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_forms() {
        // Units in brackets (the format of this version).
        let (c, skip) = column_names(
            "time [s],L1.end_a.tension [N],b.roll [deg]",
            Some("0,1,2"),
            None,
        );
        assert!(!skip);
        assert_eq!(
            c[1],
            Column {
                name: "L1.end_a.tension".into(),
                unit: "N".into()
            }
        );
        assert_eq!(c[2].unit, "deg");
        // Plain names, units on a second line.
        let (c, skip) = column_names("time,L1.end_a.tension,x", Some("s,N,-"), None);
        assert!(skip);
        assert_eq!(
            (c[0].unit.as_str(), c[1].unit.as_str(), c[2].unit.as_str()),
            ("s", "N", "-")
        );
        let (_, skip) = column_names("time,a", Some("[s],[N]"), None);
        assert!(skip);
        // Plain names, units in channels.json.
        let json = r#"{"channels": [{"name": "L1.end_a.tension", "unit": "N"}]}"#;
        let (c, skip) = column_names("time,L1.end_a.tension", Some("0.1,5"), Some(json));
        assert!(!skip);
        assert_eq!(c[1].unit, "N");
        let json = r#"{"L1.end_a.tension": {"unit": "N"}}"#;
        assert_eq!(
            column_names("time,L1.end_a.tension", None, Some(json)).0[1].unit,
            "N"
        );
        let json = r#"{"format_version": 2, "timeseries": {"time": "s", "L1.end_a.tension": "N"}}"#;
        assert_eq!(
            column_names("time,L1.end_a.tension", Some("0,1"), Some(json)).0[1].unit,
            "N"
        );
        let json = r#"{"L1.end_a.tension": "N"}"#;
        assert_eq!(
            column_names("time,L1.end_a.tension", None, Some(json)).0[1].unit,
            "N"
        );
        // A negative number on the second line is data, not units.
        assert!(!column_names("time,z", Some("-0.5,-3"), None).1);
    }

    #[test]
    fn a_row_being_written_is_skipped() {
        let dir = std::env::temp_dir().join(format!("hawser_run_files_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("timeseries.csv"),
            "time [s],a [N],b [m]\n0,1,2\n0.1,3,4\n0.2,5",
        )
        .unwrap();
        let ts = read_timeseries(&dir).unwrap();
        assert_eq!(ts.time, [0.0, 0.1]);
        assert_eq!(ts.values, [vec![1.0, 3.0], vec![2.0, 4.0]]);
        assert_eq!(ts.index("b"), Some(1));
        std::fs::write(
            dir.join("timeseries.csv"),
            "time,a,b\ns,N,m\n0,1,2\n0.1,3,4e-7\n",
        )
        .unwrap();
        let ts = read_timeseries(&dir).unwrap();
        assert_eq!((ts.channels[1].unit.as_str(), ts.values[1][1]), ("m", 4e-7));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
