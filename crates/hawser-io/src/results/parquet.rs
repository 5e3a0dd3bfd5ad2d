//! `timeseries.parquet`: the time series as a Parquet file (Snappy), for pandas, polars and
//! pyarrow. Made from `timeseries.csv` when the run ends (finished, stopped or interrupted), so
//! that the two hold the same values bit for bit (the CSV's numbers round-trip exactly) and a
//! resumed run writes the same file as an uninterrupted one; the CSV is the journal a run
//! appends to and a checkpoint cuts back. Columns are `time` and the channel names, all
//! required doubles; the file's key-value metadata gives the units (pyarrow shows it as the
//! schema's metadata).
//!
//! Built with the `parquet` crate alone (features `snap`; its column writer, without Arrow)
//! behind this crate's `parquet` feature: the Arrow crates would add minutes to a clean build
//! for nothing a table of f64 needs (docs/outputs.md has the numbers).

use super::Column;
use super::csv::{TableReader, cannot};
use parquet::basic::{Compression, LogicalType, Repetition, Type as PhysicalType};
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType};
use parquet::errors::ParquetError;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Values per row group (rows × columns), which bounds the memory the conversion takes
/// (about 32 MB of f64).
const ROW_GROUP_VALUES: usize = 1 << 22;

/// A Parquet error as an I/O error naming the file `path`.
fn io_error(path: &Path, e: ParquetError) -> std::io::Error {
    let e = match e {
        ParquetError::External(e) => match e.downcast::<std::io::Error>() {
            Ok(io) => *io,
            Err(e) => std::io::Error::other(e),
        },
        e => std::io::Error::other(e),
    };
    cannot("write", path, e)
}

/// The writer properties of hawser's Parquet files: Snappy, no dictionary, `metadata` as the
/// key-value metadata.
fn properties(metadata: &[(String, String)]) -> WriterProperties {
    WriterProperties::builder()
        .set_compression(Compression::SNAPPY)
        .set_dictionary_enabled(false)
        .set_key_value_metadata(Some(
            metadata
                .iter()
                .map(|(k, v)| KeyValue::new(k.clone(), v.clone()))
                .collect(),
        ))
        .build()
}

/// The temporary file beside `path` that a writer renames over it.
fn temporary(path: &Path) -> PathBuf {
    let mut tmp = path.as_os_str().to_owned();
    tmp.push(".tmp");
    PathBuf::from(tmp)
}

/// Writes a table of named columns of mixed types ([`Column`]: optional text as UTF-8
/// strings, optional numbers as doubles; a missing value is a null) into `path` (atomically),
/// in one row group, with `metadata` as the file's key-value metadata. For small tables (the
/// summary of a sweep: one row per case).
pub fn write_columns_parquet(
    path: &Path,
    columns: &[(String, Column)],
    metadata: &[(String, String)],
) -> std::io::Result<()> {
    let tmp = temporary(path);
    let failed = |e: ParquetError| io_error(&tmp, e);
    let fields = columns
        .iter()
        .map(|(name, c)| {
            let builder = match c {
                Column::Text(_) => Type::primitive_type_builder(name, PhysicalType::BYTE_ARRAY)
                    .with_logical_type(Some(LogicalType::String)),
                Column::Number(_) => Type::primitive_type_builder(name, PhysicalType::DOUBLE),
            };
            builder
                .with_repetition(Repetition::OPTIONAL)
                .build()
                .map(Arc::new)
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(failed)?;
    let schema = Type::group_type_builder("schema")
        .with_fields(fields)
        .build()
        .map_err(failed)?;
    let file = std::fs::File::create(&tmp).map_err(|e| cannot("create", &tmp, e))?;
    let mut writer =
        SerializedFileWriter::new(file, Arc::new(schema), Arc::new(properties(metadata)))
            .map_err(failed)?;
    let mut group = writer.next_row_group().map_err(failed)?;
    let mut data = columns.iter();
    while let Some(mut column) = group.next_column().map_err(failed)? {
        let (_, c) = data.next().expect("one column per field");
        match c {
            Column::Text(v) => {
                let levels: Vec<i16> = v.iter().map(|x| i16::from(x.is_some())).collect();
                let values: Vec<ByteArray> = v
                    .iter()
                    .flatten()
                    .map(|s| ByteArray::from(s.as_str()))
                    .collect();
                column
                    .typed::<ByteArrayType>()
                    .write_batch(&values, Some(&levels), None)
                    .map_err(failed)?;
            }
            Column::Number(v) => {
                let levels: Vec<i16> = v.iter().map(|x| i16::from(x.is_some())).collect();
                let values: Vec<f64> = v.iter().flatten().copied().collect();
                column
                    .typed::<DoubleType>()
                    .write_batch(&values, Some(&levels), None)
                    .map_err(failed)?;
            }
        }
        column.close().map_err(failed)?;
    }
    group.close().map_err(failed)?;
    writer.close().map_err(failed)?;
    std::fs::rename(&tmp, path).map_err(|e| cannot("write", path, e))
}

/// Writes `parquet` (atomically: a temporary file renamed) from the hawser CSV table `csv`:
/// one required double column per CSV column, and `metadata` as the file's key-value
/// metadata.
pub fn write_parquet(
    csv: &Path,
    parquet: &Path,
    metadata: &[(String, String)],
) -> std::io::Result<()> {
    let columns = TableReader::open(csv)?.names().len();
    let rows_per_group = (ROW_GROUP_VALUES / columns.max(1)).max(1024);
    write_in_groups(csv, parquet, metadata, rows_per_group)
}

/// [`write_parquet`] with `rows_per_group` rows in each row group.
fn write_in_groups(
    csv: &Path,
    parquet: &Path,
    metadata: &[(String, String)],
    rows_per_group: usize,
) -> std::io::Result<()> {
    let mut table = TableReader::open(csv)?;
    let tmp = temporary(parquet);
    let failed = |e: ParquetError| io_error(&tmp, e);
    let fields = table
        .names()
        .iter()
        .map(|n| {
            Type::primitive_type_builder(n, PhysicalType::DOUBLE)
                .with_repetition(Repetition::REQUIRED)
                .build()
                .map(Arc::new)
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(failed)?;
    let schema = Type::group_type_builder("schema")
        .with_fields(fields)
        .build()
        .map_err(failed)?;
    let properties = properties(metadata);
    let file = std::fs::File::create(&tmp).map_err(|e| cannot("create", &tmp, e))?;
    let mut writer =
        SerializedFileWriter::new(file, Arc::new(schema), Arc::new(properties)).map_err(failed)?;
    let mut columns: Vec<Vec<f64>> = vec![Vec::with_capacity(rows_per_group); table.names().len()];
    loop {
        let row = table.next_row()?;
        let end = row.is_none();
        if let Some(row) = row {
            for (c, x) in columns.iter_mut().zip(row) {
                c.push(*x);
            }
        }
        if columns[0].len() == rows_per_group || (end && !columns[0].is_empty()) {
            let mut group = writer.next_row_group().map_err(failed)?;
            let mut values = columns.iter_mut();
            while let Some(mut column) = group.next_column().map_err(failed)? {
                let v = values.next().expect("one column per field");
                column
                    .typed::<DoubleType>()
                    .write_batch(v, None, None)
                    .map_err(failed)?;
                column.close().map_err(failed)?;
                v.clear();
            }
            group.close().map_err(failed)?;
        }
        if end {
            break;
        }
    }
    writer.close().map_err(failed)?;
    std::fs::rename(&tmp, parquet).map_err(|e| cannot("write", parquet, e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use parquet::file::reader::{FileReader, SerializedFileReader};

    #[test]
    fn the_parquet_file_holds_the_csv_values_bit_for_bit_with_its_metadata() {
        let dir = std::env::temp_dir().join(format!("hawser_parquet_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let csv = dir.join("t.csv");
        // 5000 rows in row groups of 1000, a torn last line dropped.
        let values = |i: usize| {
            [
                i as f64 * 0.1,
                (i as f64).sin() * 1e-17,
                1e5 / (1.0 + i as f64),
            ]
        };
        let mut text = String::from("time,a.x,b.tension\n");
        for i in 0..5000 {
            let v = values(i);
            text += &format!("{:?},{:?},{:?}\n", v[0], v[1], v[2]);
        }
        text += "500.1,0.";
        std::fs::write(&csv, text).unwrap();
        let pq = dir.join("t.parquet");
        let meta = [("hawser.model_hash".to_string(), "00ff".to_string())];
        write_in_groups(&csv, &pq, &meta, 1000).unwrap();
        assert!(!dir.join("t.parquet.tmp").exists());
        let reader = SerializedFileReader::new(std::fs::File::open(&pq).unwrap()).unwrap();
        let file = reader.metadata().file_metadata();
        let kv = file.key_value_metadata().unwrap();
        assert!(
            kv.iter()
                .any(|k| k.key == "hawser.model_hash" && k.value.as_deref() == Some("00ff"))
        );
        let fields = file.schema().get_fields();
        assert_eq!(fields[1].name(), "a.x");
        assert_eq!(reader.metadata().num_row_groups(), 5);
        let mut row = 0;
        for r in reader.get_row_iter(None).unwrap() {
            let r = r.unwrap();
            for (c, want) in values(row).iter().enumerate() {
                let got = parquet::record::RowAccessor::get_double(&r, c).unwrap();
                assert_eq!(got.to_bits(), want.to_bits(), "row {row} column {c}");
            }
            row += 1;
        }
        assert_eq!(row, 5000);
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Text and number columns with missing values read back as strings, doubles (bit for
    /// bit) and nulls.
    #[test]
    fn mixed_columns_read_back_with_their_nulls() {
        use parquet::record::{Field, RowAccessor};
        let dir = std::env::temp_dir().join(format!("hawser_parquet_mixed_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let pq = dir.join("s.parquet");
        let columns = vec![
            (
                "case".to_string(),
                Column::Text(vec![Some("a".into()), Some("b, c".into())]),
            ),
            (
                "error".to_string(),
                Column::Text(vec![None, Some("diverged".into())]),
            ),
            (
                "x.max".to_string(),
                Column::Number(vec![Some(0.1 + 0.2), None]),
            ),
        ];
        write_columns_parquet(&pq, &columns, &[]).unwrap();
        let reader = SerializedFileReader::new(std::fs::File::open(&pq).unwrap()).unwrap();
        let rows: Vec<_> = reader
            .get_row_iter(None)
            .unwrap()
            .map(|r| r.unwrap())
            .collect();
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].get_string(0).unwrap(), "a");
        assert_eq!(rows[1].get_string(0).unwrap(), "b, c");
        assert!(matches!(
            rows[0].get_column_iter().nth(1).unwrap().1,
            Field::Null
        ));
        assert_eq!(rows[1].get_string(1).unwrap(), "diverged");
        assert_eq!(
            rows[0].get_double(2).unwrap().to_bits(),
            (0.1f64 + 0.2).to_bits()
        );
        assert!(matches!(
            rows[1].get_column_iter().nth(2).unwrap().1,
            Field::Null
        ));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
