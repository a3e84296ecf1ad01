//! One table of a recipe read from its file (through the crate's one reader), and the yaw
//! rate taken from it.

use super::*;
use crate::table::{read_rows, Row, Split};

/// A table read from a file: the time of each row and the columns the recipe uses.
pub(super) struct Table {
    pub(super) file: String,
    pub(super) time_s: Vec<f64>,
    pub(super) line: Vec<u64>,
    pub(super) cols: BTreeMap<String, Vec<f64>>,
    /// What the time policies did to it.
    pub(super) fixes: TimeFixes,
}

impl Table {
    pub(super) fn col(&self, name: &str, used_by: &str) -> Result<&[f64]> {
        self.cols.get(name).map(|v| v.as_slice()).ok_or_else(|| Error::missing(name, &format!("{used_by} (in {})", self.file)))
    }
}

/// A number cell: empty or "nan" = missing (NaN); anything else must be a finite number.
fn cell(fields: &[&str], j: usize, name: &str, line: u64, comma: bool) -> Result<f64> {
    let text = fields.get(j).copied().unwrap_or("");
    if text.is_empty() || text.eq_ignore_ascii_case("nan") {
        return Ok(f64::NAN);
    }
    number(text, comma).ok_or_else(|| Error::Cell { line, column: name.to_string(), message: format!("\"{text}\" is not a number") })
}

/// A cell's text as a finite number, read with a decimal comma where the table has one (the
/// import's reading, which the column guesses share).
pub(super) fn number(text: &str, comma: bool) -> Option<f64> {
    let parsed = if comma { text.replacen(',', ".", 1).parse::<f64>() } else { text.parse::<f64>() };
    parsed.ok().filter(|v| v.is_finite())
}

/// A row's time, s: from the period and the row's index, or from its time cell (seconds
/// times `scale`, or ISO 8601).
fn row_time(spec: &TableSpec, scale: f64, time_idx: Option<usize>, time_name: &str, row_n: u64, line: u64, fields: &[&str]) -> Result<f64> {
    match (spec.time.period_s, time_idx) {
        (Some(p), _) => Ok(row_n as f64 * p),
        (None, Some(j)) => {
            let v = match spec.time.format {
                TimeFormat::Seconds => {
                    cell(fields, j, time_name, line, spec.decimal_comma).map_err(|e| time_format_hint(e, fields, j))? * scale
                }
                TimeFormat::Iso8601 | TimeFormat::TimeOfDay => {
                    let text = fields.get(j).copied().unwrap_or("");
                    let (v, what) = match spec.time.format {
                        TimeFormat::Iso8601 => (parse_iso8601(text), "an ISO 8601 time"),
                        _ => (parse_time_of_day(text), "a time of day (hh:mm:ss.fff or hhmmss.fff)"),
                    };
                    v.ok_or_else(|| Error::Cell { line, column: time_name.to_string(), message: format!("\"{text}\" is not {what}") })?
                }
            };
            if v.is_nan() {
                return Err(Error::Cell { line, column: time_name.to_string(), message: "empty time".into() });
            }
            Ok(v)
        }
        (None, None) => Err(recipe_err(&format!("table {}", spec.id), "time needs a column or a period_s")),
    }
}

/// A time cell that is not a number but reads as a date-time or a time of day: the error
/// names the format that reads it.
fn time_format_hint(e: Error, fields: &[&str], j: usize) -> Error {
    let text = fields.get(j).copied().unwrap_or("");
    let format = if parse_iso8601(text).is_some() {
        "iso8601"
    } else if parse_time_of_day(text).is_some() {
        "time_of_day"
    } else {
        return e;
    };
    match e {
        Error::Cell { line, column, message } => {
            Error::Cell { line, column, message: format!("{message}; it reads as a time with time.format = \"{format}\"") }
        }
        e => e,
    }
}

/// Named columns and their field index.
type Fields = Vec<(String, usize)>;

/// The field index of each wanted column and of the time, from the header.
fn resolve_columns(spec: &TableSpec, wanted: &BTreeSet<String>, h: &[String]) -> Result<(Fields, Option<usize>)> {
    let index_of = |name: &str| h.iter().position(|x| x == name);
    let mut idx = Vec::with_capacity(wanted.len());
    for name in wanted {
        let j = index_of(name)
            .ok_or_else(|| Error::missing(name, &format!("named by the recipe for table {}; the header has: {}", spec.id, h.join(", "))))?;
        idx.push((name.clone(), j));
    }
    let time_idx = match &spec.time.column {
        Some(c) => Some(index_of(c).ok_or_else(|| Error::missing(c, &format!("the time of table {}", spec.id)))?),
        None => None,
    };
    Ok((idx, time_idx))
}

/// Reads the columns `wanted` (and the time) of one table, streaming.
pub(super) fn read_table(spec: &TableSpec, wanted: &BTreeSet<String>, files: &mut dyn Files) -> Result<Table> {
    if spec.format == TableFormat::Gpx {
        return super::gpx::read_gpx(spec, wanted, files);
    }
    let file = spec.file.clone();
    let at = |e: Error| -> Error { e.within(&file) };
    let scale = time_unit(&spec.time.unit)?;
    let reader = files.open(&spec.file)?;
    let mut header: Option<Vec<String>> = spec.columns.clone();
    // Indices of the wanted columns and of the time, once the header is known.
    let mut idx: Vec<(String, usize)> = Vec::new();
    let mut time_idx: Option<usize> = None;
    let mut resolved = false;
    let time_name = spec.time.column.clone().unwrap_or_else(|| "time".into());
    let mut t = Table { file: file.clone(), time_s: Vec::new(), line: Vec::new(), cols: BTreeMap::new(), fixes: TimeFixes::default() };
    let mut latest = f64::NEG_INFINITY;
    let nmea = spec.format == TableFormat::Nmea;
    // Days counted on for a time of day (`past_midnight`).
    let mut day_s = 0.0;
    let mut cols: Vec<Vec<f64>> = Vec::new();
    let mut row_n: u64 = 0;
    // The first fields of rows `record` left out (up to 5), to name when none was kept.
    let mut other_records: Vec<String> = Vec::new();
    let mut on_row = |line: u64, fields: &[&str]| -> Result<()> {
        let Some(h) = &header else {
            header = Some(fields.iter().map(|f| f.to_string()).collect());
            return Ok(());
        };
        if !resolved {
            (idx, time_idx) = resolve_columns(spec, wanted, h)?;
            cols = vec![Vec::new(); idx.len()];
            resolved = true;
        }
        if is_other_record(spec, fields, &mut other_records) {
            return Ok(());
        }
        let mut time = row_time(spec, scale, time_idx, &time_name, row_n, line, fields)?;
        if spec.time.format == TimeFormat::TimeOfDay && spec.time.period_s.is_none() {
            time = past_midnight(time, &mut day_s, latest);
        }
        check_step(&spec.time, time, t.time_s.last().copied(), latest, line, &time_name)?;
        latest = latest.max(time);
        for (k, (name, j)) in idx.iter().enumerate() {
            cols[k].push(value(spec, nmea, fields, *j, name, line)?);
        }
        t.time_s.push(time);
        t.line.push(line);
        row_n += 1;
        Ok(())
    };
    let split = match spec.format {
        TableFormat::Whitespace => Split::Whitespace,
        _ if spec.delimiter == ',' => Split::Csv,
        _ => Split::Delimited(spec.delimiter as u8),
    };
    let mut each = |r: Row| -> Result<()> {
        if nmea {
            on_row(r.line, &without_checksum(r.fields))
        } else {
            on_row(r.line, r.fields)
        }
    };
    read_rows(reader, 0, split, spec.skip_lines, Default::default(), &mut |_, _| Ok(false), &mut each).map_err(at)?;
    if header.is_none() {
        return Err(at(Error::File("empty file: no header row".into())));
    }
    if t.time_s.is_empty() {
        return Err(at(no_data_rows(spec, &other_records)));
    }
    finish_table(spec, &mut t, idx.into_iter().map(|(name, _)| name), cols);
    Ok(t)
}

/// A row of another record than the table's (`record`): left out, its first field kept to
/// name (up to 5) when no row of the table's record is found.
fn is_other_record(spec: &TableSpec, fields: &[&str], other_records: &mut Vec<String>) -> bool {
    let Some(rec) = &spec.record else { return false };
    if fields.first() == Some(&rec.as_str()) {
        return false;
    }
    let first = fields.first().copied().unwrap_or("");
    if other_records.len() < 5 && !other_records.iter().any(|r| r == first) {
        other_records.push(first.to_string());
    }
    true
}

/// A wanted column's value in a row; in an NMEA log, a hemisphere letter as a sign (for
/// positions.kind = "nmea").
fn value(spec: &TableSpec, nmea: bool, fields: &[&str], j: usize, name: &str, line: u64) -> Result<f64> {
    match (nmea, fields.get(j).copied()) {
        (true, Some("N" | "E")) => Ok(1.0),
        (true, Some("S" | "W")) => Ok(-1.0),
        _ => cell(fields, j, name, line, spec.decimal_comma),
    }
}

/// An NMEA-like sentence's fields without the trailing `*hh` checksum of its last one.
fn without_checksum<'a>(fields: &[&'a str]) -> Vec<&'a str> {
    let mut fields = fields.to_vec();
    if let Some(last) = fields.last_mut() {
        if let Some(star) = last.find('*') {
            *last = &last[..star];
        }
    }
    fields
}

/// A table that kept no row: why, naming the records its rows start with when it has one.
fn no_data_rows(spec: &TableSpec, other_records: &[String]) -> Error {
    let why = match (&spec.record, other_records.is_empty()) {
        (Some(rec), false) => {
            let seen: Vec<String> = other_records.iter().map(|r| format!("\"{r}\"")).collect();
            format!(": no row starts with record \"{rec}\" (rows start with {})", seen.join(", "))
        }
        _ => String::new(),
    };
    Error::File(format!("table {} has no data rows{why}", spec.id))
}

/// A table's rows as read (in file order, steps checked): put in time order by the time
/// policies, made relative and offset as the spec says, and given their named columns.
pub(super) fn finish_table(spec: &TableSpec, t: &mut Table, names: impl Iterator<Item = String>, mut cols: Vec<Vec<f64>>) {
    t.fixes = put_in_time_order(&spec.time, &mut t.time_s, &mut t.line, &mut cols);
    let first = t.time_s[0];
    for x in t.time_s.iter_mut() {
        if spec.time.relative {
            *x -= first;
        }
        *x += spec.offset_s;
    }
    for (name, v) in names.zip(cols) {
        t.cols.insert(name, v);
    }
}

/// Times, yaw rates (deg/s, CCW positive) and, when projected, the up vector.
pub(super) type YawRate = (Vec<f64>, Vec<f64>, Option<[f64; 3]>);

/// The yaw rate of a table in deg/s, CCW positive (and the up vector when projected).
pub(super) fn yaw_rate(spec: &RateSpec, tables: &BTreeMap<String, Table>, field: &str) -> Result<YawRate> {
    let t = tables.get(&spec.table).ok_or_else(|| recipe_err(&format!("{field}.table"), format!("no table with id \"{}\"", spec.table)))?;
    let unit = rate_unit(&spec.unit, &format!("{field}.unit"))?;
    if !(spec.scale.is_finite() && spec.scale != 0.0 && spec.offset.is_finite()) {
        return Err(recipe_err(&format!("{field}.scale"), "scale must be finite and non-zero, offset finite"));
    }
    let k = unit * spec.scale * spec.sense_factor();
    let conv = |x: f64| (x - spec.offset) * k;
    match (&spec.column, &spec.axes, &spec.gravity) {
        (Some(c), None, None) => {
            let v = t.col(c, field)?;
            Ok((t.time_s.clone(), v.iter().map(|&x| conv(x)).collect(), None))
        }
        (None, Some(axes), Some(g)) => {
            if axes.len() != 3 || g.axes.len() != 3 {
                return Err(recipe_err(field, "axes and gravity.axes need three columns each"));
            }
            let gyro: Vec<&[f64]> = axes.iter().map(|a| t.col(a, field)).collect::<Result<_>>()?;
            let signs = |v: &Option<Vec<f64>>, f: &str| -> Result<[f64; 3]> {
                match v {
                    None => Ok([1.0; 3]),
                    Some(v) if v.len() == 3 && v.iter().all(|x| *x == 1.0 || *x == -1.0) => Ok([v[0], v[1], v[2]]),
                    Some(_) => Err(recipe_err(f, "needs three factors, each 1 or -1")),
                }
            };
            let gs = signs(&spec.signs, &format!("{field}.signs"))?;
            let acs = signs(&g.signs, &format!("{field}.gravity.signs"))?;
            let gt = match &g.table {
                Some(id) => {
                    tables.get(id).ok_or_else(|| recipe_err(&format!("{field}.gravity.table"), format!("no table with id \"{id}\"")))?
                }
                None => t,
            };
            let acc: Vec<&[f64]> = g.axes.iter().map(|a| gt.col(a, &format!("{field}.gravity"))).collect::<Result<_>>()?;
            let t0 = gt.time_s[0];
            let mut m = [0.0; 3];
            let mut n = 0usize;
            for i in 0..gt.time_s.len() {
                if gt.time_s[i] - t0 >= g.first_s {
                    break;
                }
                let a = [acc[0][i] * acs[0], acc[1][i] * acs[1], acc[2][i] * acs[2]];
                if a.iter().all(|x| x.is_finite()) {
                    for j in 0..3 {
                        m[j] += a[j];
                    }
                    n += 1;
                }
            }
            let norm = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
            if n == 0 || norm == 0.0 {
                return Err(Error::data(format!(
                    "{}: no accelerometer values in the first {} s to find the up direction",
                    gt.file, g.first_s
                )));
            }
            let up = [m[0] / norm, m[1] / norm, m[2] / norm];
            let rate = (0..t.time_s.len()).map(|i| (0..3).map(|j| conv(gyro[j][i]) * gs[j] * up[j]).sum::<f64>()).collect();
            Ok((t.time_s.clone(), rate, Some(up)))
        }
        _ => Err(recipe_err(field, "give either `column` (one axis) or `axes` with `gravity` (projection on up)")),
    }
}

impl RateSpec {
    fn sense_factor(&self) -> f64 {
        self.positive.factor()
    }
}
