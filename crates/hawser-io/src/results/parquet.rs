//! `timeseries.parquet`: the time series as a Parquet file (Snappy), for pandas, polars and
//! pyarrow. Made from `timeseries.csv` when the run ends (finished, stopped or interrupted), so
//! that the two hold the same values bit for bit (the CSV's numbers round-trip exactly) and a
//! resumed run writes the same file as an uninterrupted one; the CSV is the journal a run
//! appends to and a checkpoint cuts back. Columns are `time` and the channel names, all f64;
//! each field's Arrow metadata and the file's key-value metadata give the units.
//!
//! Built with `parquet` (features `arrow`, `snap`), `arrow-array` and `arrow-schema` behind
//! this crate's `parquet` feature; never the `arrow` umbrella crate, whose build takes minutes.

use super::csv::{TableReader, cannot};
use arrow_array::{ArrayRef, Float64Array, RecordBatch};
use arrow_schema::{DataType, Field, Schema};
use parquet::arrow::ArrowWriter;
use parquet::basic::Compression;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

/// Values per row group (rows × columns), which bounds the memory the conversion takes
/// (about 32 MB of f64).
const ROW_GROUP_VALUES: usize = 1 << 22;

/// Writes `parquet` (atomically: a temporary file renamed) from the hawser CSV table `csv`:
/// one f64 column per CSV column, with `units[i]` as column i's `unit` field metadata, and
/// `metadata` as the file's key-value metadata and the Arrow schema's metadata.
pub fn write_parquet(
    csv: &Path,
    parquet: &Path,
    units: &[&str],
    metadata: &[(String, String)],
) -> std::io::Result<()> {
    let columns = TableReader::open(csv)?.names().len();
    let rows_per_group = (ROW_GROUP_VALUES / columns.max(1)).max(1024);
    write_in_groups(csv, parquet, units, metadata, rows_per_group)
}

/// [`write_parquet`] with `rows_per_group` rows in each row group.
fn write_in_groups(
    csv: &Path,
    parquet: &Path,
    units: &[&str],
    metadata: &[(String, String)],
    rows_per_group: usize,
) -> std::io::Result<()> {
    let mut table = TableReader::open(csv)?;
    let names = table.names().to_vec();
    if names.len() != units.len() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "{} has {} columns, expected {}",
                csv.display(),
                names.len(),
                units.len()
            ),
        ));
    }
    let fields: Vec<Field> = names
        .iter()
        .zip(units)
        .map(|(n, u)| {
            Field::new(n, DataType::Float64, false)
                .with_metadata(HashMap::from([("unit".to_string(), u.to_string())]))
        })
        .collect();
    // In the Arrow schema (what pyarrow's `schema.metadata` shows) and in the file's
    // key-value metadata (what every Parquet reader sees).
    let schema = Arc::new(Schema::new_with_metadata(
        fields,
        metadata.iter().cloned().collect(),
    ));
    let properties = WriterProperties::builder()
        .set_compression(Compression::SNAPPY)
        .set_dictionary_enabled(false)
        .set_max_row_group_row_count(Some(rows_per_group))
        .set_key_value_metadata(Some(
            metadata
                .iter()
                .map(|(k, v)| KeyValue::new(k.clone(), v.clone()))
                .collect(),
        ))
        .build();
    let mut tmp = parquet.as_os_str().to_owned();
    tmp.push(".tmp");
    let tmp = std::path::PathBuf::from(tmp);
    let file = std::fs::File::create(&tmp).map_err(|e| cannot("create", &tmp, e))?;
    let failed = |e: parquet::errors::ParquetError| {
        let e = match e {
            parquet::errors::ParquetError::External(e) => match e.downcast::<std::io::Error>() {
                Ok(io) => *io,
                Err(e) => std::io::Error::other(e),
            },
            e => std::io::Error::other(e),
        };
        cannot("write", &tmp, e)
    };
    let mut writer =
        ArrowWriter::try_new(file, schema.clone(), Some(properties)).map_err(failed)?;
    let mut columns: Vec<Vec<f64>> = vec![Vec::with_capacity(rows_per_group); names.len()];
    loop {
        let row = table.next_row()?;
        let end = row.is_none();
        if let Some(row) = row {
            for (c, x) in columns.iter_mut().zip(row) {
                c.push(*x);
            }
        }
        if columns[0].len() == rows_per_group || (end && !columns[0].is_empty()) {
            let arrays: Vec<ArrayRef> = columns
                .iter_mut()
                .map(|c| Arc::new(Float64Array::from(std::mem::take(c))) as ArrayRef)
                .collect();
            let batch = RecordBatch::try_new(schema.clone(), arrays)
                .map_err(|e| cannot("write", &tmp, std::io::Error::other(e)))?;
            writer.write(&batch).map_err(failed)?;
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
    use arrow_array::Array;
    use parquet::arrow::arrow_reader::ParquetRecordBatchReaderBuilder;

    #[test]
    fn the_parquet_file_holds_the_csv_values_bit_for_bit_with_units() {
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
        write_in_groups(&csv, &pq, &["s", "m", "N"], &meta, 1000).unwrap();
        assert!(!dir.join("t.parquet.tmp").exists());
        let reader =
            ParquetRecordBatchReaderBuilder::try_new(std::fs::File::open(&pq).unwrap()).unwrap();
        let schema = reader.schema().clone();
        assert_eq!(schema.metadata()["hawser.model_hash"], "00ff");
        assert_eq!(schema.field(2).name(), "b.tension");
        assert_eq!(schema.field(2).metadata()["unit"], "N");
        assert_eq!(reader.metadata().num_row_groups(), 5);
        let kv = reader
            .metadata()
            .file_metadata()
            .key_value_metadata()
            .unwrap();
        assert!(kv.iter().any(|k| k.key == "hawser.model_hash"));
        let mut row = 0;
        for batch in reader.build().unwrap() {
            let batch = batch.unwrap();
            for r in 0..batch.num_rows() {
                for (c, want) in values(row).iter().enumerate() {
                    let col = batch
                        .column(c)
                        .as_any()
                        .downcast_ref::<Float64Array>()
                        .unwrap();
                    assert!(!col.is_null(r));
                    assert_eq!(
                        col.value(r).to_bits(),
                        want.to_bits(),
                        "row {row} column {c}"
                    );
                }
                row += 1;
            }
        }
        assert_eq!(row, 5000);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
