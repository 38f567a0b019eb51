//! One part of a sweep as a Parquet file: a required `index` column (the input's index in the whole
//! sweep, `int64`), then one nullable `double` column per cell of the input and of the result, and
//! the sweep's description as the file's key–value metadata. Uncompressed, one row group: a part is
//! written once and read whole.

use super::part_error::PartError;
use parquet::basic::{Repetition, Type as PhysicalType};
use parquet::column::reader::ColumnReader;
use parquet::column::writer::ColumnWriter;
use parquet::file::metadata::KeyValue;
use parquet::file::properties::WriterProperties;
use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::types::Type;
use std::fs::File;
use std::path::Path;
use std::sync::Arc;

/// The name of the column holding each row's index in the whole sweep.
pub(crate) const INDEX: &str = "index";

/// What a part file holds: the indices `first..first + rows`, the cells row after row, and the
/// metadata.
pub(crate) struct PartData {
    pub first: usize,
    pub cells: Vec<Option<f64>>,
    pub metadata: Vec<(String, String)>,
}

fn unreadable(path: &Path, reason: impl std::fmt::Display) -> PartError {
    PartError::Unreadable {
        path: path.to_owned(),
        reason: reason.to_string(),
    }
}

fn io(path: &Path, source: std::io::Error) -> PartError {
    PartError::Io {
        path: path.to_owned(),
        source,
    }
}

fn schema(names: &[String]) -> parquet::errors::Result<Type> {
    let mut fields = vec![Arc::new(
        Type::primitive_type_builder(INDEX, PhysicalType::INT64)
            .with_repetition(Repetition::REQUIRED)
            .build()?,
    )];
    for name in names {
        fields.push(Arc::new(
            Type::primitive_type_builder(name, PhysicalType::DOUBLE)
                .with_repetition(Repetition::OPTIONAL)
                .build()?,
        ));
    }
    Type::group_type_builder("sweep")
        .with_fields(fields)
        .build()
}

/// Writes `part` (cells of `names.len()` columns) to `path`: first to a temporary file beside it,
/// then renamed over it, so a reader (or a rerun) sees either no part or a whole one.
pub(crate) fn write(path: &Path, names: &[String], part: &PartData) -> Result<(), PartError> {
    let tmp = path.with_extension("parquet.partial");
    let file = File::create(&tmp).map_err(|e| io(&tmp, e))?;
    write_to(file, names, part).map_err(|e| unreadable(&tmp, e))?;
    std::fs::rename(&tmp, path).map_err(|e| io(path, e))
}

fn write_to(file: File, names: &[String], part: &PartData) -> parquet::errors::Result<()> {
    let metadata = part
        .metadata
        .iter()
        .map(|(k, v)| KeyValue::new(k.clone(), v.clone()))
        .collect();
    let props = WriterProperties::builder()
        .set_key_value_metadata(Some(metadata))
        .build();
    let mut writer = SerializedFileWriter::new(file, Arc::new(schema(names)?), Arc::new(props))?;
    let width = names.len();
    let rows = part.cells.len().checked_div(width).unwrap_or(0);
    let mut group = writer.next_row_group()?;
    let mut column = 0;
    while let Some(mut col) = group.next_column()? {
        match col.untyped() {
            ColumnWriter::Int64ColumnWriter(w) => {
                let index: Vec<i64> = (part.first..part.first + rows).map(|k| k as i64).collect();
                w.write_batch(&index, None, None)?;
            }
            ColumnWriter::DoubleColumnWriter(w) => {
                let cells = part.cells.iter().skip(column - 1).step_by(width);
                let values: Vec<f64> = cells.clone().flatten().copied().collect();
                let defined: Vec<i16> = cells.map(|c| i16::from(c.is_some())).collect();
                w.write_batch(&values, Some(&defined), None)?;
            }
            _ => unreachable!("the schema has only int64 and double columns"),
        }
        col.close()?;
        column += 1;
    }
    group.close()?;
    writer.close()?;
    Ok(())
}

/// Reads the part at `path`, whose columns must be `index` then `names`.
pub(crate) fn read(path: &Path, names: &[String]) -> Result<PartData, PartError> {
    let file = File::open(path).map_err(|e| io(path, e))?;
    let reader = SerializedFileReader::new(file).map_err(|e| unreadable(path, e))?;
    let meta = reader.metadata().file_metadata();
    let found: Vec<&str> = meta
        .schema_descr()
        .columns()
        .iter()
        .map(|c| c.name())
        .collect();
    let expected: Vec<&str> = std::iter::once(INDEX)
        .chain(names.iter().map(String::as_str))
        .collect();
    if found != expected {
        return Err(PartError::Foreign {
            path: path.to_owned(),
            key: "columns".into(),
            expected: expected.join(","),
            found: found.join(","),
        });
    }
    let metadata = meta
        .key_value_metadata()
        .map(|kv| {
            kv.iter()
                .map(|kv| (kv.key.clone(), kv.value.clone().unwrap_or_default()))
                .collect()
        })
        .unwrap_or_default();
    let rows = usize::try_from(meta.num_rows()).map_err(|e| unreadable(path, e))?;
    let width = names.len();
    let mut cells = vec![None; rows * width];
    let mut index = Vec::with_capacity(rows);
    let mut filled = vec![0; width];
    for g in 0..reader.num_row_groups() {
        let group = reader.get_row_group(g).map_err(|e| unreadable(path, e))?;
        for c in 0..=width {
            let column = group
                .get_column_reader(c)
                .map_err(|e| unreadable(path, e))?;
            read_column(column, c, width, &mut index, &mut cells, &mut filled)
                .map_err(|e| unreadable(path, e))?;
        }
    }
    if index.len() != rows || filled.iter().any(|&f| f != rows) {
        return Err(unreadable(path, "fewer rows than its metadata says"));
    }
    let first = index.first().map_or(0, |&k| k as usize);
    if index
        .iter()
        .enumerate()
        .any(|(j, &k)| k as usize != first + j)
    {
        return Err(unreadable(path, "its indices are not consecutive"));
    }
    Ok(PartData {
        first,
        cells,
        metadata,
    })
}

/// Reads one column chunk: the index column (`c` = 0) into `index`, a cell column into every
/// `width`-th cell from `filled[c − 1]` rows on.
fn read_column(
    column: ColumnReader,
    c: usize,
    width: usize,
    index: &mut Vec<i64>,
    cells: &mut [Option<f64>],
    filled: &mut [usize],
) -> Result<(), String> {
    const BATCH: usize = 8192;
    match column {
        ColumnReader::Int64ColumnReader(mut r) if c == 0 => loop {
            let (records, _, _) = r
                .read_records(BATCH, None, None, index)
                .map_err(|e| e.to_string())?;
            if records == 0 {
                return Ok(());
            }
        },
        ColumnReader::DoubleColumnReader(mut r) if c > 0 => loop {
            let (mut values, mut defined) = (Vec::new(), Vec::new());
            let (records, _, _) = r
                .read_records(BATCH, Some(&mut defined), None, &mut values)
                .map_err(|e| e.to_string())?;
            if records == 0 {
                return Ok(());
            }
            let mut values = values.into_iter();
            for d in defined {
                let row = filled[c - 1];
                let cell = cells
                    .get_mut(row * width + c - 1)
                    .ok_or("more rows than its metadata says")?;
                *cell = if d > 0 { values.next() } else { None };
                filled[c - 1] += 1;
            }
        },
        _ => Err(format!("column {c} has the wrong type")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A part read back by the Parquet reader directly: the schema (an int64 index, nullable
    /// doubles), the key–value metadata, and the cells with their nulls, bit for bit.
    #[test]
    fn a_part_reads_back_with_its_schema_metadata_and_nulls() {
        let dir = std::env::temp_dir().join(format!("lagrange-part-file-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("p.parquet");
        let names = vec!["x".to_owned(), "t".to_owned()];
        let part = PartData {
            first: 40,
            cells: vec![
                Some(0.1),
                None,
                Some(-0.0),
                Some(f64::MIN_POSITIVE),
                Some(3.0),
                None,
            ],
            metadata: vec![
                ("integrator".into(), "Rk4".into()),
                ("h".into(), "0.001".into()),
            ],
        };
        write(&path, &names, &part).unwrap();

        let reader = SerializedFileReader::new(File::open(&path).unwrap()).unwrap();
        let meta = reader.metadata().file_metadata();
        assert_eq!(meta.num_rows(), 3);
        let columns = meta.schema_descr().columns().to_vec();
        let kinds: Vec<_> = columns
            .iter()
            .map(|c| (c.name().to_owned(), c.physical_type(), c.max_def_level()))
            .collect();
        assert_eq!(
            kinds,
            [
                ("index".to_owned(), PhysicalType::INT64, 0),
                ("x".to_owned(), PhysicalType::DOUBLE, 1),
                ("t".to_owned(), PhysicalType::DOUBLE, 1)
            ]
        );
        let kv = meta.key_value_metadata().unwrap();
        assert!(kv
            .iter()
            .any(|kv| kv.key == "integrator" && kv.value.as_deref() == Some("Rk4")));

        let back = read(&path, &names).unwrap();
        assert_eq!(back.first, 40);
        assert_eq!(back.metadata, part.metadata);
        let bits = |c: &[Option<f64>]| c.iter().map(|x| x.map(f64::to_bits)).collect::<Vec<_>>();
        assert_eq!(bits(&back.cells), bits(&part.cells));
        // Other column names: a part of another sweep.
        let other = vec!["x".to_owned(), "y".to_owned()];
        assert!(matches!(
            read(&path, &other),
            Err(PartError::Foreign { .. })
        ));
        std::fs::remove_dir_all(&dir).ok();
    }
}
