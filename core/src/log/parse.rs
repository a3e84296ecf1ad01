//! The CSV v1 log parser: metadata lines, a header naming the known columns, then rows,
//! read through the crate's one table reader (`crate::table`). Every error names the line
//! and, for a cell, the column.

use super::{Column, DriveLog, LogMeta, ParseOptions};
use crate::error::{Error, Result};
use crate::table::{read_rows, Row, Split};
use std::io::Read;

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

/// The header: which field holds which known column.
struct Header {
    line: u64,
    map: Vec<Option<Column>>,
    time_field: usize,
}

impl Header {
    /// Maps each header field to a known column (or None = ignored); time_s is required.
    fn new(fields: &[&str], line: u64) -> Result<Header> {
        let mut seen: [Option<usize>; Column::ALL.len()] = [None; Column::ALL.len()];
        let mut map = Vec::with_capacity(fields.len());
        for (j, name) in fields.iter().enumerate() {
            let col = Column::from_name(name);
            if let Some(c) = col {
                if let Some(first) = seen[c.index()] {
                    let message = format!("duplicate column {} (fields {} and {})", c.name(), first + 1, j + 1);
                    return Err(Error::Line { line, message });
                }
                seen[c.index()] = Some(j);
            }
            map.push(col);
        }
        let Some(time_field) = seen[Column::TimeS.index()] else {
            // Starts with NO_TIME_COLUMN (a literal here, as time_order_message's).
            let message = format!("missing required column time_s (the header has: {})", fields.join(", "));
            return Err(Error::Line { line, message });
        };
        Ok(Header { line, map, time_field })
    }
}

/// As `parse_log_with`, calling `progress(bytes read so far)` every 65 536 rows (for a
/// progress bar while a large file is parsed off the main thread).
pub fn parse_log_progress<R: Read>(reader: R, opts: ParseOptions, progress: &mut dyn FnMut(u64)) -> Result<DriveLog> {
    parse_rows::<true>(reader, opts, false, progress)
}

/// A v1 log whose time repeats or steps back a little (a logger writing a sample twice, or a
/// row late): its rows put in time order by the import's default time policies (rows of one
/// time merged, each column the mean of its present values; rows up to 1 s late sorted in),
/// with counts of what they did. A larger step back (a clock reset) is still an error.
pub fn parse_log_in_time_order<R: Read>(reader: R, opts: ParseOptions) -> Result<(DriveLog, crate::import::TimeFixes)> {
    in_time_order(parse_rows::<false>(reader, opts, false, &mut |_| {})?)
}

/// A v1 log's rows in file order (for `accept`, which cuts it at clock resets before putting
/// each part in order). `parts_in_order`: a time that repeats or steps back by at most 1 s is
/// refused where it is, as the strict parser refuses it, so a bad cell further on is not
/// named first; a clock reset (back by more) starts a part and is not refused. `lines_before`:
/// the file's lines before the log's first.
pub(super) fn parse_log_unordered<R: Read>(reader: R, parts_in_order: bool, lines_before: u64) -> Result<DriveLog> {
    parse_rows::<false>(reader, ParseOptions { lines_before, ..Default::default() }, parts_in_order, &mut |_| {})
}

/// The first row whose time does not strictly increase, refused as the strict parser refuses it.
pub(super) fn strictly_increasing(log: &DriveLog) -> Result<()> {
    let t = log.time_s();
    match (1..t.len()).find(|&i| t[i] <= t[i - 1]) {
        None => Ok(()),
        Some(i) => {
            let line = |i: usize| log.line.get(i).copied().unwrap_or(i as u64 + 2);
            Err(Error::Cell { line: line(i), column: "time_s".into(), message: time_order_message(t[i], t[i - 1], line(i - 1)) })
        }
    }
}

/// Rows in file order put in time order as [`parse_log_in_time_order`] does.
pub(super) fn in_time_order(mut log: DriveLog) -> Result<(DriveLog, crate::import::TimeFixes)> {
    let mut time = log.columns[Column::TimeS.index()].take().unwrap_or_default();
    let present: Vec<usize> = (0..log.columns.len()).filter(|&i| log.columns[i].is_some()).collect();
    let mut cols: Vec<Vec<f64>> = present.iter().map(|&i| log.columns[i].take().unwrap_or_default()).collect();
    let fixes = crate::import::put_v1_in_time_order(&mut time, &mut log.line, &mut cols)?;
    log.columns[Column::TimeS.index()] = Some(time);
    for (i, c) in present.into_iter().zip(cols) {
        log.columns[i] = Some(c);
    }
    Ok((log, fixes))
}

/// The rows of a v1 log; with `STRICT`, time must strictly increase (each row against the one
/// before), otherwise the rows are left in file order (with `parts_in_order`, only a clock
/// reset may step back).
#[inline(always)]
fn parse_rows<const STRICT: bool>(
    reader: impl Read,
    opts: ParseOptions,
    parts_in_order: bool,
    progress: &mut dyn FnMut(u64),
) -> Result<DriveLog> {
    let mut meta = LogMeta::default();
    let mut preamble = |line: u64, text: &str| -> Result<bool> {
        let t = text.trim();
        match t.strip_prefix('#') {
            _ if t.is_empty() => Ok(true),
            Some(rest) => parse_meta_line(rest, line, &mut meta).map(|_| true),
            None => Ok(false),
        }
    };
    let mut header: Option<Header> = None;
    let mut log = DriveLog::default();
    let mut prev_time: Option<(f64, u64)> = None;
    let mut rows = 0usize;
    read_rows(reader, opts.lines_before, Split::Csv, 0, opts.limits, &mut preamble, &mut |r: Row| {
        let Some(h) = &header else {
            let h = Header::new(r.fields, r.line)?;
            for c in h.map.iter().flatten() {
                log.columns[c.index()] = Some(Vec::new());
            }
            header = Some(h);
            return Ok(());
        };
        rows += 1;
        if rows.is_multiple_of(65_536) {
            progress(r.byte);
        }
        if rows > opts.max_rows {
            return Err(Error::File(format!(
                "too many rows: more than {} (line {}); split the log or raise max_rows",
                opts.max_rows, r.line
            )));
        }
        data_row::<STRICT>(h, &r, &mut prev_time, parts_in_order, &mut log)
    })?;
    let Some(h) = header else {
        return Err(Error::File("empty file: no header row".into()));
    };
    if rows == 0 {
        return Err(Error::File(format!("no data rows: the file has a header (line {}) but no rows", h.line)));
    }
    log.meta = meta;
    Ok(log)
}

/// How the parser's refusal of a time that repeats or steps back ends (`data_row`;
/// `accept::Refusal::of`, whose CLI and Python hints the tests check).
pub(super) const TIME_ORDER_REFUSAL: &str = "time must strictly increase";

/// What a clock reset's refusal says (`accept::Refusal::of`).
pub(super) const CLOCK_RESET: &str = "a clock reset?";

/// Whether a cell error is a refusal of a row's time order, the parser's or the time-order
/// fix's ("time 4.9 goes back from 5 ...", which may name a reset and the row before): both
/// start with "time ", where a bad cell's message quotes the cell (`accept::Refusal::of`).
pub(super) fn is_time_order(column: &str, message: &str) -> bool {
    column == "time_s" && message.starts_with("time ")
}

/// Whether a cell error is a `time_s` cell that is not a number (`parse_cell`'s words): a
/// logger's own time (date-times) perhaps, which the import's draft may read (`import::hint`).
#[cfg(feature = "fs")]
pub(crate) fn is_bad_time_cell(e: &Error) -> bool {
    matches!(e, Error::Cell { column, message, .. } if column == "time_s" && message.ends_with("is not a number"))
}

/// How the refusal of a header without `time_s` starts: a table that is no v1 log (a
/// logger's own export), which a recipe reads (`accept::Refusal::of`, `import::hint`).
pub(super) const NO_TIME_COLUMN: &str = "missing required column time_s";

/// How the refusal of a row with fewer cells than the header ends (`accept::Refusal::of`).
pub(super) const CUT_ROW: &str = " (truncated row?)";

/// Why time `v` on a row after time `pt` (on line `pl`) is refused; a step back of more than
/// 1 s is named a clock reset (a logger restarted), which no time-order fix mends.
fn time_order_message(v: f64, pt: f64, pl: u64) -> String {
    let what = if v == pt { "repeats" } else { "goes back from" };
    let reset = if crate::import::is_clock_reset(pt, v) { " a clock reset?" } else { "" };
    // Ends with TIME_ORDER_REFUSAL (a literal here: the const in the format string grows the
    // size-capped browser module).
    format!("time {v} {what} {pt} on line {pl}:{reset} time must strictly increase")
}

/// One data row into the columns; time must be present and, with `STRICT`, strictly increase
/// (with `parts_in_order`, unless it steps back as a clock reset does).
#[inline(always)]
fn data_row<const STRICT: bool>(
    h: &Header,
    r: &Row,
    prev_time: &mut Option<(f64, u64)>,
    parts_in_order: bool,
    log: &mut DriveLog,
) -> Result<()> {
    let line = r.line;
    if r.fields.len() != h.map.len() {
        let hint = if r.fields.len() < h.map.len() { " (truncated row?)" } else { "" };
        return Err(Error::Line { line, message: format!("row has {} fields, the header has {}{}", r.fields.len(), h.map.len(), hint) });
    }
    for (j, col) in h.map.iter().enumerate() {
        let Some(c) = col else { continue };
        let v = parse_cell(r.fields[j], line, c.name())?;
        c.check_physical(v).map_err(|message| Error::Cell { line, column: c.name().into(), message })?;
        if j == h.time_field {
            if v.is_nan() {
                return Err(Error::Cell { line, column: c.name().into(), message: "empty, but every row needs a time".into() });
            }
            if let Some((pt, pl)) = *prev_time {
                if v <= pt && (STRICT || parts_in_order && !crate::import::is_clock_reset(pt, v)) {
                    return Err(Error::Cell { line, column: c.name().into(), message: time_order_message(v, pt, pl) });
                }
            }
            *prev_time = Some((v, line));
        }
        if let Some(vec) = log.columns[c.index()].as_mut() {
            vec.push(v);
        }
    }
    log.line.push(line);
    Ok(())
}

/// Empty cell = NaN (missing); anything else must be a finite number.
fn parse_cell(text: &str, line: u64, column: &str) -> Result<f64> {
    if text.is_empty() {
        return Ok(f64::NAN);
    }
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
