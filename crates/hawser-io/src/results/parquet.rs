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
    let rows_per_group = (ROW_GROUP_VALUES / names.len().max(1)).max(1024);
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
