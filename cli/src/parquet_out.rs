//! Fleet rows to a Parquet file (the parquet crate's column writer; snappy-compressed). The
//! columns are core's `fleet::CSV_HEADER`, in order, every one nullable: text for names,
//! warnings and errors, 64-bit integers for counts, doubles for the rest. The values come
//! from each row's serde form, so the columns cannot drift from the JSON keys.

use gyrodrift::fleet::{DriveRow, CSV_HEADER};
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
use parquet::schema::parser::parse_message_type;
use serde_json::Value;
use std::io::Write;
use std::sync::Arc;

#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Text,
    Int,
    Double,
}

fn kind(column: &str) -> Kind {
    match column {
        "file" | "name" | "still_source" | "warnings" | "not_scored" | "error" | "error_code" => Kind::Text,
        "part" | "parts" | "rows" => Kind::Int,
        _ => Kind::Double,
    }
}

/// The Parquet schema of the fleet rows.
fn schema() -> String {
    let fields: Vec<String> = CSV_HEADER
        .split(',')
        .map(|c| match kind(c) {
            Kind::Text => format!("OPTIONAL BYTE_ARRAY {c} (UTF8);"),
            Kind::Int => format!("OPTIONAL INT64 {c};"),
            Kind::Double => format!("OPTIONAL DOUBLE {c};"),
        })
        .collect();
    format!("message drive_rows {{ {} }}", fields.join(" "))
}

/// Writes `rows` as one row group.
pub fn write<W: Write + Send>(out: W, rows: &[DriveRow]) -> parquet::errors::Result<()> {
    let schema = Arc::new(parse_message_type(&schema())?);
    let props = Arc::new(WriterProperties::builder().set_compression(parquet::basic::Compression::SNAPPY).build());
    let mut writer = SerializedFileWriter::new(out, schema, props)?;
    let values: Vec<Value> = rows.iter().map(|r| serde_json::to_value(r).unwrap_or(Value::Null)).collect();
    let mut group = writer.next_row_group()?;
    let mut columns = CSV_HEADER.split(',');
    while let Some(mut col) = group.next_column()? {
        let name = columns.next().unwrap_or_default();
        let cells: Vec<&Value> = values.iter().map(|v| v.get(name).unwrap_or(&Value::Null)).collect();
        let def: Vec<i16> = cells.iter().map(|c| i16::from(!c.is_null())).collect();
        let present = cells.iter().filter(|c| !c.is_null());
        match kind(name) {
            Kind::Text => {
                let v: Vec<ByteArray> = present.map(|c| ByteArray::from(c.as_str().unwrap_or_default())).collect();
                col.typed::<ByteArrayType>().write_batch(&v, Some(&def), None)?;
            }
            Kind::Int => {
                let v: Vec<i64> = present.map(|c| c.as_i64().unwrap_or_default()).collect();
                col.typed::<Int64Type>().write_batch(&v, Some(&def), None)?;
            }
            Kind::Double => {
                let v: Vec<f64> = present.map(|c| c.as_f64().unwrap_or(f64::NAN)).collect();
                col.typed::<DoubleType>().write_batch(&v, Some(&def), None)?;
            }
        }
        col.close()?;
    }
    group.close()?;
    writer.close()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use parquet::file::reader::{FileReader, SerializedFileReader};

    #[test]
    fn rows_round_trip_with_nulls_for_an_error_row() {
        let mut ok = DriveRow::failed("a.csv", "");
        ok.error = None;
        ok.rows = 1200;
        ok.ne_psi_hdr_deg_per_min = Some(0.25);
        let bad = DriveRow::failed("b.csv", "line 3, column gyro_dps: not a number");
        let path = std::env::temp_dir().join(format!("gyrodrift-parquet-test-{}.parquet", std::process::id()));
        write(std::fs::File::create(&path).unwrap(), &[ok, bad]).unwrap();
        let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
        std::fs::remove_file(&path).unwrap();
        let meta = reader.metadata();
        assert_eq!(meta.file_metadata().num_rows(), 2);
        let names: Vec<String> = meta.file_metadata().schema_descr().columns().iter().map(|c| c.name().to_string()).collect();
        assert_eq!(names.join(","), CSV_HEADER);
        let rows: Vec<String> = reader.get_row_iter(None).unwrap().map(|r| r.unwrap().to_string()).collect();
        assert!(
            rows[0].contains("file: \"a.csv\"") && rows[0].contains("rows: 1200") && rows[0].contains("ne_psi_hdr_deg_per_min: 0.25"),
            "{}",
            rows[0]
        );
        assert!(rows[0].contains("error: null"), "{}", rows[0]);
        assert!(
            rows[1].contains("error: \"line 3, column gyro_dps: not a number\"") && rows[1].contains("ne_psi_hdr_deg_per_min: null"),
            "{}",
            rows[1]
        );
    }
}
