//! The canonical drive-log CSV v1 (methods.md, "Canonical drive-log CSV"): `# key: value`
//! metadata lines, one header row, then rows; free column order, unknown columns ignored,
//! an empty cell is a missing value. Parsed streaming from any `Read` with the `csv` crate.
//!
//! Missing cells are stored as NaN: finite input is enforced, so NaN can mean nothing else.

use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read, Write};

/// The columns of the v1 format, in the order they are written.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Column {
    TimeS,
    GyroDps,
    TempC,
    RefHeadingDeg,
    SpeedMps,
    OdoLeftM,
    OdoRightM,
    TableRateDps,
}

impl Column {
    pub const ALL: [Column; 8] = [
        Column::TimeS,
        Column::GyroDps,
        Column::TempC,
        Column::RefHeadingDeg,
        Column::SpeedMps,
        Column::OdoLeftM,
        Column::OdoRightM,
        Column::TableRateDps,
    ];

    /// The header name of the column in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            Column::TimeS => "time_s",
            Column::GyroDps => "gyro_dps",
            Column::TempC => "temp_c",
            Column::RefHeadingDeg => "ref_heading_deg",
            Column::SpeedMps => "speed_mps",
            Column::OdoLeftM => "odo_left_m",
            Column::OdoRightM => "odo_right_m",
            Column::TableRateDps => "table_rate_dps",
        }
    }

    pub fn from_name(name: &str) -> Option<Column> {
        Column::ALL.iter().copied().find(|c| c.name() == name)
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// `# key: value` lines before the header. Known keys are typed; others are kept as text.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct LogMeta {
    pub name: Option<String>,
    pub wheelbase_m: Option<f64>,
    pub bias_s: Option<f64>,
    pub description: Option<String>,
    /// Any other `# key: value` pairs, kept verbatim.
    pub other: BTreeMap<String, String>,
}

/// A parsed log: one vector per present column, all of the same length as `time_s`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct DriveLog {
    pub meta: LogMeta,
    /// 1-based line number in the file of each row (for error messages after parsing).
    pub line: Vec<u64>,
    columns: [Option<Vec<f64>>; 8],
}

/// Limits for untrusted input.
#[derive(Debug, Clone, Copy)]
pub struct ParseOptions {
    /// More data rows than this is an error rather than an out-of-memory abort.
    pub max_rows: usize,
}

impl Default for ParseOptions {
    fn default() -> Self {
        // 30 M rows ~ 830 h at 10 Hz, ~2 GB of columns: beyond that a log is a mistake.
        ParseOptions { max_rows: 30_000_000 }
    }
}

impl DriveLog {
    /// An empty log with the given columns present (time_s always is).
    pub fn with_columns(columns: &[Column]) -> Self {
        let mut log = DriveLog::default();
        log.columns[Column::TimeS.index()] = Some(Vec::new());
        for c in columns {
            log.columns[c.index()] = Some(Vec::new());
        }
        log
    }

    /// Appends one row; `values` gives the cells of present columns (NaN = missing).
    /// Used by the simulator and importers; time must increase (checked by `validate`).
    pub fn push_row(&mut self, values: &[(Column, f64)]) {
        let n = self.len();
        for col in self.columns.iter_mut().flatten() {
            col.push(f64::NAN);
        }
        for &(c, v) in values {
            if let Some(col) = self.columns[c.index()].as_mut() {
                col[n] = v;
            }
        }
        self.line.push(n as u64 + 2);
    }

    pub fn len(&self) -> usize {
        self.time_s().len()
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    pub fn time_s(&self) -> &[f64] {
        self.columns[0].as_deref().unwrap_or(&[])
    }
    /// The column's cells (NaN = empty cell), or None if the header lacks it.
    pub fn column(&self, c: Column) -> Option<&[f64]> {
        self.columns[c.index()].as_deref()
    }
    /// The column's cells to change in place (the robustness battery's error injection).
    pub fn column_mut(&mut self, c: Column) -> Option<&mut [f64]> {
        self.columns[c.index()].as_deref_mut()
    }
    /// Keeps only the rows from index `first` on (e.g. to cut a stationary lead-in).
    pub fn drop_first_rows(&mut self, first: usize) {
        let first = first.min(self.len());
        for col in self.columns.iter_mut().flatten() {
            col.drain(..first);
        }
        self.line.drain(..first.min(self.line.len()));
    }
    /// The column, or an error naming it and the method that needs it.
    pub fn require(&self, c: Column, needed_by: &str) -> Result<&[f64]> {
        self.column(c).ok_or_else(|| Error::missing(c.name(), needed_by))
    }
    pub fn has(&self, c: Column) -> bool {
        self.columns[c.index()].is_some()
    }
    pub fn present_columns(&self) -> Vec<Column> {
        Column::ALL.iter().copied().filter(|&c| self.has(c)).collect()
    }

    /// Duration T_d in minutes: last minus first time_s of the whole log (methods.md detail 5).
    pub fn duration_min(&self) -> f64 {
        let t = self.time_s();
        match (t.first(), t.last()) {
            (Some(a), Some(b)) => (b - a) / 60.0,
            _ => 0.0,
        }
    }

    /// What kind of log this is, from its columns: turntable, robot, drive or static.
    pub fn kind(&self) -> LogKind {
        if self.has(Column::TableRateDps) {
            LogKind::Turntable
        } else if self.has(Column::OdoLeftM) && self.has(Column::OdoRightM) {
            LogKind::Robot
        } else if self.has(Column::RefHeadingDeg) {
            LogKind::Drive
        } else {
            LogKind::Static
        }
    }

    /// The static-bias window length: the option, else `# bias_s:`, else 20 s (detail 1).
    pub fn bias_s(&self, option: Option<f64>) -> f64 {
        option.or(self.meta.bias_s).unwrap_or(20.0)
    }

    /// Writes the log as CSV v1 (metadata, header of present columns, rows).
    /// Numbers are written with Rust's shortest round-trip formatting, so parse(write(x)) == x.
    pub fn write_csv<W: Write>(&self, out: W) -> Result<()> {
        let mut out = std::io::BufWriter::new(out);
        let m = &self.meta;
        if let Some(v) = &m.name {
            writeln!(out, "# name: {v}")?;
        }
        if let Some(v) = &m.description {
            writeln!(out, "# description: {v}")?;
        }
        if let Some(v) = m.wheelbase_m {
            writeln!(out, "# wheelbase_m: {v}")?;
        }
        if let Some(v) = m.bias_s {
            writeln!(out, "# bias_s: {v}")?;
        }
        for (k, v) in &m.other {
            writeln!(out, "# {k}: {v}")?;
        }
        let cols: Vec<(Column, &[f64])> = Column::ALL.iter().filter_map(|&c| self.column(c).map(|v| (c, v))).collect();
        let header: Vec<&str> = cols.iter().map(|(c, _)| c.name()).collect();
        writeln!(out, "{}", header.join(","))?;
        let mut buf = String::new();
        for i in 0..self.len() {
            buf.clear();
            for (j, (_, v)) in cols.iter().enumerate() {
                if j > 0 {
                    buf.push(',');
                }
                let x = v[i];
                if x.is_finite() {
                    use std::fmt::Write as _;
                    let _ = write!(buf, "{x}");
                }
            }
            buf.push('\n');
            out.write_all(buf.as_bytes())?;
        }
        out.flush()?;
        Ok(())
    }
}

impl DriveLog {
    /// A log from columns (e.g. handed over from a parsing worker), checked as the parser
    /// checks: equal lengths, a finite strictly increasing time, finite or missing values.
    pub fn from_columns(meta: LogMeta, line: Vec<u64>, columns: Vec<(Column, Vec<f64>)>) -> Result<DriveLog> {
        let mut log = DriveLog { meta, line, ..DriveLog::default() };
        for (c, v) in columns {
            if log.columns[c.index()].is_some() {
                return Err(Error::File(format!("duplicate column {}", c.name())));
            }
            log.columns[c.index()] = Some(v);
        }
        let n = log.columns[Column::TimeS.index()].as_ref().map(Vec::len).ok_or_else(|| Error::missing("time_s", "every log needs it"))?;
        if n == 0 {
            return Err(Error::File("no data rows".into()));
        }
        if log.line.len() != n {
            log.line = (0..n as u64).map(|i| i + 2).collect();
        }
        for c in Column::ALL {
            if let Some(v) = log.column(c) {
                if v.len() != n {
                    return Err(Error::File(format!("column {} has {} values, time_s has {n}", c.name(), v.len())));
                }
                if let Some(i) = v.iter().position(|x| x.is_infinite()) {
                    return Err(Error::Cell { line: log.line[i], column: c.name().into(), message: "not a finite number".into() });
                }
            }
        }
        let t = log.time_s();
        for i in 0..n {
            if t[i].is_nan() || (i > 0 && !(t[i] > t[i - 1])) {
                return Err(Error::Cell {
                    line: log.line[i],
                    column: "time_s".into(),
                    message: "time must be present and strictly increase".into(),
                });
            }
        }
        Ok(log)
    }

    /// The present columns with their values (for handing a parsed log to another thread).
    pub fn columns(&self) -> Vec<(Column, &[f64])> {
        Column::ALL.iter().filter_map(|&c| self.column(c).map(|v| (c, v))).collect()
    }
}

/// The kind of a log, decided by its columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum LogKind {
    Drive,
    Robot,
    Turntable,
    Static,
}

/// Parses a CSV v1 log with the default limits.
pub fn parse_log<R: Read>(reader: R) -> Result<DriveLog> {
    parse_log_with(reader, ParseOptions::default())
}

/// Parses from a string (the wasm package and tests).
pub fn parse_log_str(text: &str) -> Result<DriveLog> {
    parse_log(text.as_bytes())
}

/// Parses a CSV v1 log, streaming: memory grows with the known columns only.
pub fn parse_log_with<R: Read>(reader: R, opts: ParseOptions) -> Result<DriveLog> {
    parse_log_progress(reader, opts, &mut |_| {})
}

/// As `parse_log_with`, calling `progress(bytes read so far)` every 65 536 rows (for a
/// progress bar while a large file is parsed off the main thread).
pub fn parse_log_progress<R: Read>(reader: R, opts: ParseOptions, progress: &mut dyn FnMut(u64)) -> Result<DriveLog> {
    let mut reader = BufReader::with_capacity(1 << 16, reader);
    let mut meta = LogMeta::default();
    let mut line_no: u64 = 0;
    let mut raw = Vec::new();
    // Metadata and blank lines before the header.
    let header_line = loop {
        raw.clear();
        let n = reader.read_until(b'\n', &mut raw)?;
        if n == 0 {
            return Err(Error::File("empty file: no header row".into()));
        }
        line_no += 1;
        if line_no == 1 && raw.starts_with(b"\xEF\xBB\xBF") {
            raw.drain(..3);
        }
        let text = std::str::from_utf8(&raw).map_err(|_| Error::Line { line: line_no, message: "not valid UTF-8 text".into() })?;
        let trimmed = text.trim();
        if trimmed.is_empty() {
            continue;
        }
        if let Some(rest) = trimmed.strip_prefix('#') {
            parse_meta_line(rest, line_no, &mut meta)?;
            continue;
        }
        break raw.clone();
    };
    let header_line_no = line_no;

    let mut rdr = csv::ReaderBuilder::new().has_headers(true).flexible(true).from_reader(std::io::Cursor::new(header_line).chain(reader));
    let header = rdr.byte_headers().map_err(|e| csv_error(e, header_line_no - 1))?.clone();

    // Map each header field to a known column (or None = ignored).
    let mut map: Vec<Option<Column>> = Vec::with_capacity(header.len());
    let mut seen: [Option<usize>; 8] = [None; 8];
    for (j, field) in header.iter().enumerate() {
        let name = std::str::from_utf8(field).unwrap_or("").trim();
        let col = Column::from_name(name);
        if let Some(c) = col {
            if let Some(first) = seen[c.index()] {
                return Err(Error::Line {
                    line: header_line_no,
                    message: format!("duplicate column {} (fields {} and {})", c.name(), first + 1, j + 1),
                });
            }
            seen[c.index()] = Some(j);
        }
        map.push(col);
    }
    if seen[Column::TimeS.index()].is_none() {
        let names: Vec<String> = header.iter().map(|f| String::from_utf8_lossy(f).into_owned()).collect();
        return Err(Error::Line {
            line: header_line_no,
            message: format!("missing required column time_s (the header has: {})", names.join(", ")),
        });
    }

    let mut log = DriveLog { meta, ..DriveLog::default() };
    for c in Column::ALL {
        if seen[c.index()].is_some() {
            log.columns[c.index()] = Some(Vec::new());
        }
    }
    let time_field = seen[Column::TimeS.index()].unwrap_or(0);
    let n_fields = header.len();
    let mut record = csv::ByteRecord::new();
    let mut prev_time: Option<(f64, u64)> = None;
    let mut rows = 0usize;
    loop {
        let more = rdr.read_byte_record(&mut record).map_err(|e| csv_error(e, header_line_no - 1))?;
        if !more {
            break;
        }
        let line = record.position().map(|p| p.line()).unwrap_or(0) + header_line_no - 1;
        if record.len() != n_fields {
            let hint = if record.len() < n_fields { " (truncated row?)" } else { "" };
            return Err(Error::Line { line, message: format!("row has {} fields, the header has {}{}", record.len(), n_fields, hint) });
        }
        rows += 1;
        if rows.is_multiple_of(65_536) {
            progress(record.position().map_or(0, |p| p.byte()));
        }
        if rows > opts.max_rows {
            return Err(Error::File(format!("too many rows: more than {} (line {line}); split the log or raise max_rows", opts.max_rows)));
        }
        for (j, col) in map.iter().enumerate() {
            let Some(c) = col else { continue };
            let cell = &record[j];
            let v = parse_cell(cell, line, c.name())?;
            if j == time_field {
                if v.is_nan() {
                    return Err(Error::Cell { line, column: c.name().into(), message: "empty, but every row needs a time".into() });
                }
                if let Some((pt, pl)) = prev_time {
                    if v <= pt {
                        let what = if v == pt { "repeats" } else { "goes back from" };
                        return Err(Error::Cell {
                            line,
                            column: c.name().into(),
                            message: format!("time {v} {what} {pt} on line {pl}: time must strictly increase"),
                        });
                    }
                }
                prev_time = Some((v, line));
            }
            if let Some(vec) = log.columns[c.index()].as_mut() {
                vec.push(v);
            }
        }
        log.line.push(line);
    }
    if rows == 0 {
        return Err(Error::File(format!("no data rows: the file has a header (line {header_line_no}) but no rows")));
    }
    Ok(log)
}

/// Empty (or whitespace) cell = NaN (missing); anything else must be a finite number.
fn parse_cell(cell: &[u8], line: u64, column: &str) -> Result<f64> {
    let cell = cell.trim_ascii();
    if cell.is_empty() {
        return Ok(f64::NAN);
    }
    let text =
        std::str::from_utf8(cell).map_err(|_| Error::Cell { line, column: column.into(), message: "not valid UTF-8 text".into() })?;
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(Error::Cell { line, column: column.into(), message: format!("\"{text}\" is not a finite number") }),
        Err(_) => Err(Error::Cell { line, column: column.into(), message: format!("\"{}\" is not a number", shorten(text)) }),
    }
}

fn shorten(s: &str) -> String {
    if s.chars().count() > 40 {
        let cut: String = s.chars().take(40).collect();
        format!("{cut}...")
    } else {
        s.to_string()
    }
}

fn parse_meta_line(rest: &str, line: u64, meta: &mut LogMeta) -> Result<()> {
    let Some((key, value)) = rest.split_once(':') else {
        return Ok(()); // a plain comment
    };
    let key = key.trim();
    let value = value.trim();
    let number = |name: &str| -> Result<f64> {
        match value.parse::<f64>() {
            Ok(v) if v.is_finite() && v >= 0.0 => Ok(v),
            _ => Err(Error::Line { line, message: format!("metadata {name}: \"{value}\" is not a number >= 0") }),
        }
    };
    match key {
        "name" => meta.name = Some(value.to_string()),
        "description" => meta.description = Some(value.to_string()),
        "wheelbase_m" => {
            let v = number("wheelbase_m")?;
            if v == 0.0 {
                return Err(Error::Line { line, message: "metadata wheelbase_m: must be > 0".into() });
            }
            meta.wheelbase_m = Some(v)
        }
        "bias_s" => meta.bias_s = Some(number("bias_s")?),
        _ => {
            meta.other.insert(key.to_string(), value.to_string());
        }
    }
    Ok(())
}

/// Maps a csv-crate error to ours; `offset` = lines consumed before the csv reader started.
fn csv_error(e: csv::Error, offset: u64) -> Error {
    let line = e.position().map(|p| p.line() + offset);
    let message = match e.kind() {
        csv::ErrorKind::Io(io) => return Error::Io(io.to_string()),
        csv::ErrorKind::Utf8 { .. } => "not valid UTF-8 text".to_string(),
        _ => e.to_string(),
    };
    match line {
        Some(line) => Error::Line { line, message },
        None => Error::File(message),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        parse_log_str(text).unwrap_err().to_string()
    }

    #[test]
    fn parses_metadata_free_order_unknown_and_empty_cells() {
        let text = "# name: City 1\n# wheelbase_m: 0.5\n# bias_s: 10\n# vehicle: Forester\n\
                    gyro_dps,extra,time_s\n1.5,x,0.0\n,y,0.1\n-2,z,0.2\n";
        let log = parse_log_str(text).unwrap();
        assert_eq!(log.meta.name.as_deref(), Some("City 1"));
        assert_eq!(log.meta.wheelbase_m, Some(0.5));
        assert_eq!(log.meta.bias_s, Some(10.0));
        assert_eq!(log.meta.other.get("vehicle").map(String::as_str), Some("Forester"));
        assert_eq!(log.time_s(), &[0.0, 0.1, 0.2]);
        let g = log.column(Column::GyroDps).unwrap();
        assert_eq!(g[0], 1.5);
        assert!(g[1].is_nan());
        assert_eq!(g[2], -2.0);
        assert_eq!(log.line, vec![6, 7, 8]);
        assert!(!log.has(Column::RefHeadingDeg));
    }

    #[test]
    fn crlf_bom_and_spaces() {
        let log = parse_log_str("\u{feff}time_s , gyro_dps\r\n0, 1\r\n1 ,2\r\n").unwrap();
        assert_eq!(log.time_s(), &[0.0, 1.0]);
        assert_eq!(log.column(Column::GyroDps).unwrap(), &[1.0, 2.0]);
    }

    #[test]
    fn empty_file_and_header_only() {
        assert_eq!(err(""), "empty file: no header row");
        assert_eq!(err("# name: x\n\n"), "empty file: no header row");
        assert!(err("time_s,gyro_dps\n").contains("no data rows"));
    }

    #[test]
    fn missing_and_duplicate_columns() {
        let e = err("gyro_dps\n1\n");
        assert!(e.contains("line 1") && e.contains("missing required column time_s"), "{e}");
        let e = err("time_s,gyro_dps,gyro_dps\n0,1,1\n");
        assert_eq!(e, "line 1: duplicate column gyro_dps (fields 2 and 3)");
    }

    #[test]
    fn bad_cells_name_line_and_column() {
        let e = err("# name: a\ntime_s,gyro_dps\n0,1\n1,1.2.3\n");
        assert_eq!(e, "line 4, column gyro_dps: \"1.2.3\" is not a number");
        let e = err("time_s,gyro_dps\n0,NaN\n");
        assert_eq!(e, "line 2, column gyro_dps: \"NaN\" is not a finite number");
        let e = err("time_s,gyro_dps\n0,1\n1,inf\n");
        assert_eq!(e, "line 3, column gyro_dps: \"inf\" is not a finite number");
        let e = err("time_s,gyro_dps\n,1\n");
        assert_eq!(e, "line 2, column time_s: empty, but every row needs a time");
    }

    #[test]
    fn non_increasing_time_names_both_lines() {
        let e = err("time_s,gyro_dps\n0,1\n1,1\n1,1\n");
        assert_eq!(e, "line 4, column time_s: time 1 repeats 1 on line 3: time must strictly increase");
        let e = err("time_s,gyro_dps\n0,1\n2,1\n1.5,1\n");
        assert!(e.starts_with("line 4, column time_s: time 1.5 goes back from 2 on line 3"), "{e}");
    }

    #[test]
    fn truncated_last_line() {
        let e = err("time_s,gyro_dps,temp_c\n0,1,20\n0.1,1");
        assert_eq!(e, "line 3: row has 2 fields, the header has 3 (truncated row?)");
    }

    #[test]
    fn bad_metadata() {
        let e = err("# wheelbase_m: wide\ntime_s\n0\n");
        assert_eq!(e, "line 1: metadata wheelbase_m: \"wide\" is not a number >= 0");
        let e = err("# bias_s: -3\ntime_s\n0\n");
        assert!(e.contains("line 1") && e.contains("bias_s"));
    }

    #[test]
    fn row_limit_is_an_error_not_an_abort() {
        let text = "time_s\n0\n1\n2\n";
        let e = parse_log_with(text.as_bytes(), ParseOptions { max_rows: 2 }).unwrap_err();
        assert!(e.to_string().contains("too many rows"), "{e}");
    }

    #[test]
    fn invalid_utf8_is_an_error() {
        let e = parse_log(&b"time_s,gyro_dps\n0,\xff\n"[..]).unwrap_err().to_string();
        assert!(e.contains("line 2"), "{e}");
    }

    #[test]
    fn write_then_parse_round_trips() {
        let mut log = DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]);
        log.meta.name = Some("t".into());
        log.meta.bias_s = Some(5.0);
        log.push_row(&[(Column::TimeS, 0.0), (Column::GyroDps, 0.1 + 0.2)]);
        log.push_row(&[(Column::TimeS, 0.1), (Column::RefHeadingDeg, -12.5)]);
        let mut buf = Vec::new();
        log.write_csv(&mut buf).unwrap();
        let back = parse_log(&buf[..]).unwrap();
        assert_eq!(back.meta, log.meta);
        assert_eq!(back.time_s(), log.time_s());
        assert_eq!(back.column(Column::GyroDps).unwrap()[0], 0.1 + 0.2);
        assert!(back.column(Column::GyroDps).unwrap()[1].is_nan());
        assert_eq!(back.column(Column::RefHeadingDeg).unwrap()[1], -12.5);
    }

    #[test]
    fn from_columns_checks_like_the_parser() {
        let log = parse_log_str("time_s,gyro_dps\n0,1\n1,\n").unwrap();
        let cols: Vec<(Column, Vec<f64>)> = log.columns().into_iter().map(|(c, v)| (c, v.to_vec())).collect();
        let back = DriveLog::from_columns(log.meta.clone(), log.line.clone(), cols).unwrap();
        assert_eq!(back.time_s(), log.time_s());
        assert_eq!(back.line, vec![2, 3]);
        let bad = DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::TimeS, vec![0.0, 0.0])]);
        assert!(bad.unwrap_err().to_string().contains("strictly increase"));
        let bad = DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::TimeS, vec![0.0, 1.0]), (Column::GyroDps, vec![1.0])]);
        assert!(bad.is_err());
        assert!(DriveLog::from_columns(LogMeta::default(), vec![], vec![(Column::GyroDps, vec![1.0])]).is_err());
    }

    #[test]
    fn progress_is_reported_on_large_inputs() {
        let mut text = String::from("time_s\n");
        for i in 0..140_000 {
            text.push_str(&format!("{i}\n"));
        }
        let mut calls = vec![];
        parse_log_progress(text.as_bytes(), ParseOptions::default(), &mut |b| calls.push(b)).unwrap();
        assert_eq!(calls.len(), 2);
        assert!(calls[0] > 0 && calls[1] > calls[0]);
    }

    #[test]
    fn kind_from_columns() {
        assert_eq!(DriveLog::with_columns(&[Column::GyroDps]).kind(), LogKind::Static);
        assert_eq!(DriveLog::with_columns(&[Column::GyroDps, Column::RefHeadingDeg]).kind(), LogKind::Drive);
        assert_eq!(DriveLog::with_columns(&[Column::OdoLeftM, Column::OdoRightM]).kind(), LogKind::Robot);
        assert_eq!(DriveLog::with_columns(&[Column::TableRateDps]).kind(), LogKind::Turntable);
    }
}
