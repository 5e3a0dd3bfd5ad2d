//! Reading a run's files back: the time series (`timeseries.csv`) with the units of its
//! columns (`channels.json`) and the line snapshots (`snapshots/LINE.csv`), for the design
//! statistics at the end of a run and for `hawser plot`, of a finished or a running run (a
//! row still being written is dropped by [`TableReader`]). Result format
//! [`FORMAT_VERSION`] only: a folder written in format 1 (units in the column names, no
//! `channels.json`) is refused with its version named.

use crate::results::{FORMAT_VERSION, TableReader, read_units};
use hawser::math::Real;
use std::path::Path;

/// A column's name and unit.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// Channel name, e.g. `L1.end_b.tension`.
    pub name: String,
    /// Unit, e.g. `N` (empty when `channels.json` does not name one).
    pub unit: String,
}

/// The error for a folder in another result format.
fn other_format(dir: &Path, what: &str) -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidData,
        format!(
            "{}: {what}: written in result format_version 1 (units in the column names), this \
             hawser reads format_version {FORMAT_VERSION}; hint: run the scenario again with \
             this hawser",
            dir.display()
        ),
    )
}

/// Opens `timeseries.csv` in `dir` with the units of its columns from `channels.json`.
fn open_timeseries(dir: &Path) -> std::io::Result<(TableReader, Vec<Column>)> {
    let reader = TableReader::open(&dir.join("timeseries.csv"))?;
    if reader.names().iter().any(|n| n.ends_with(']')) {
        return Err(other_format(
            dir,
            "timeseries.csv has units in its column names",
        ));
    }
    if !dir.join("channels.json").exists() {
        return Err(other_format(dir, "no channels.json"));
    }
    let units = read_units(dir)?;
    let columns = reader
        .names()
        .iter()
        .map(|n| Column {
            name: n.clone(),
            unit: units["timeseries"][n.as_str()]
                .as_str()
                .unwrap_or_default()
                .to_string(),
        })
        .collect();
    Ok((reader, columns))
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

/// Streams the rows of `timeseries.csv` in `dir`: `row(time, channel values)` for each
/// complete row, channels in file order (the `time` column, the first, left out). Returns the
/// channels.
pub fn for_each_sample(
    dir: &Path,
    mut row: impl FnMut(Real, &[Real]),
) -> std::io::Result<Vec<Column>> {
    let (mut reader, mut columns) = open_timeseries(dir)?;
    if columns.first().is_none_or(|c| c.name != "time") {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "{}: the first column is not `time`",
                dir.join("timeseries.csv").display()
            ),
        ));
    }
    columns.remove(0);
    while let Some(r) = reader.next_row()? {
        row(r[0], &r[1..]);
    }
    Ok(columns)
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
/// snapshot, columns `time`, `arc_length`, `x`, `y`, `z` and `tension` found by name).
pub fn read_snapshots(path: &Path) -> std::io::Result<Vec<Snapshot>> {
    let mut reader = TableReader::open(path)?;
    let find = |name: &str| {
        reader
            .names()
            .iter()
            .position(|c| c == name)
            .ok_or_else(|| {
                std::io::Error::new(
                    std::io::ErrorKind::InvalidData,
                    format!(
                        "{}: no `{name}` column (result format_version {FORMAT_VERSION} names \
                         them without units)",
                        path.display()
                    ),
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
    while let Some(r) = reader.next_row()? {
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
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_being_written_is_dropped_and_format_1_is_refused() {
        let dir = std::env::temp_dir().join(format!("hawser_run_files_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("channels.json"),
            r#"{"format_version": 2, "timeseries": {"time": "s", "a": "N", "b": "m"}}"#,
        )
        .unwrap();
        std::fs::write(
            dir.join("timeseries.csv"),
            "time,a,b\n0.0,1,2\n0.1,3,4e-7\n0.2,5",
        )
        .unwrap();
        let ts = read_timeseries(&dir).unwrap();
        assert_eq!(ts.time, [0.0, 0.1]);
        assert_eq!(ts.values, [vec![1.0, 3.0], vec![2.0, 4e-7]]);
        assert_eq!(ts.index("b"), Some(1));
        assert_eq!(ts.channels[1].unit, "m");
        std::fs::write(dir.join("timeseries.csv"), "time [s],a [N],b [m]\n0,1,2\n").unwrap();
        let e = read_timeseries(&dir).unwrap_err().to_string();
        assert!(e.contains("format_version 1"), "{e}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
